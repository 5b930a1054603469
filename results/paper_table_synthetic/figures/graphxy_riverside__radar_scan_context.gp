# radarpr figure (screen style): matching graph at the F1-max threshold, top view.
# Run `gnuplot graphxy_riverside__radar_scan_context.gp` in this folder: it reads graphxy_riverside__radar_scan_context.csv (blocks separated by two
# blank lines, selected with `index`) and writes graphxy_riverside__radar_scan_context.svg, graphxy_riverside__radar_scan_context.png and graphxy_riverside__radar_scan_context.pdf.
set datafile separator comma
set terminal svg size 1200,640 font 'sans,12' background rgb 'white' noenhanced
set output 'graphxy_riverside__radar_scan_context.svg'
set title 'riverside, RadarSC: matching graph at the F1-max threshold (0.1054), top view'
set xlabel 'x [m]'
set ylabel 'y [m]'
set xtics 100
set ytics -100, 100
set grid
set size ratio -1
set key outside right top vertical Left reverse box
set key title 'F1-max threshold: d ≤ 0.1054'
plot 'graphxy_riverside__radar_scan_context.csv' skip 1 index 0 using 1:2 with lines lw 1 dt 1 lc rgb '#404040' title 'trajectory', \
      'graphxy_riverside__radar_scan_context.csv' skip 1 index 1 using 1:2:4:5 with vectors nohead lw 0.8 lc rgb '#a01a9641' title 'TP (192)', \
      'graphxy_riverside__radar_scan_context.csv' skip 1 index 2 using 1:2:4:5 with vectors nohead lw 1.5 lc rgb '#d7191c' title 'FP (209)'
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,640 font 'sans,11' background rgb 'white' noenhanced
} else {
  set terminal png size 1200,640 background rgb 'white' noenhanced
}
set output 'graphxy_riverside__radar_scan_context.png'
replot
# A gnuplot without cairo draws no PDF (the SVG and PNG are there).
if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {
  set terminal pdfcairo size 12in,6.4in font 'sans,10' fontscale 1 noenhanced
  set output 'graphxy_riverside__radar_scan_context.pdf'
  replot
}
unset output
