# radarpr figure (screen style): matching graph at the F1-max threshold, top view.
# Run `gnuplot graphxy_city_sessions__open_radvlad.gp` in this folder: it reads graphxy_city_sessions__open_radvlad.csv (blocks separated by two
# blank lines, selected with `index`) and writes graphxy_city_sessions__open_radvlad.svg, graphxy_city_sessions__open_radvlad.png and graphxy_city_sessions__open_radvlad.pdf.
set datafile separator comma
set terminal svg size 1200,640 font 'sans,12' background rgb 'white' noenhanced
set output 'graphxy_city_sessions__open_radvlad.svg'
set title 'city_sessions, RadVLAD: matching graph at the F1-max threshold (1.355), top view'
set xlabel 'x [m]'
set ylabel 'y [m]'
set xtics 100
set ytics -100, 100
set grid
set size ratio -1
set key outside right top vertical Left reverse box
set key title 'F1-max threshold: d ≤ 1.355'
plot 'graphxy_city_sessions__open_radvlad.csv' skip 1 index 0 using 1:2 with lines lw 4 lc rgb '#c8c8c8' title 'database trajectory', \
      'graphxy_city_sessions__open_radvlad.csv' skip 1 index 1 using 1:2 with lines lw 1 dt 2 lc rgb '#404040' title 'query trajectory', \
      'graphxy_city_sessions__open_radvlad.csv' skip 1 index 2 using 1:2:4:5 with vectors nohead lw 0.8 lc rgb '#a01a9641' title 'TP (99)', \
      'graphxy_city_sessions__open_radvlad.csv' skip 1 index 3 using 1:2:4:5 with vectors nohead lw 1.5 lc rgb '#d7191c' title 'FP (4)'
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,640 font 'sans,11' background rgb 'white' noenhanced
} else {
  set terminal png size 1200,640 background rgb 'white' noenhanced
}
set output 'graphxy_city_sessions__open_radvlad.png'
replot
# A gnuplot without cairo draws no PDF (the SVG and PNG are there).
if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {
  set terminal pdfcairo size 12in,6.4in font 'sans,10' fontscale 1 noenhanced
  set output 'graphxy_city_sessions__open_radvlad.pdf'
  replot
}
unset output
