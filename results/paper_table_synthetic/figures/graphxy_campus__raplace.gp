# radarpr figure (screen style): matching graph at the F1-max threshold, top view.
# Run `gnuplot graphxy_campus__raplace.gp` in this folder: it reads graphxy_campus__raplace.csv (blocks separated by two
# blank lines, selected with `index`) and writes graphxy_campus__raplace.svg, graphxy_campus__raplace.png and graphxy_campus__raplace.pdf.
set datafile separator comma
set terminal svg size 1200,640 font 'sans,12' background rgb 'white' noenhanced
set output 'graphxy_campus__raplace.svg'
set title 'campus, Raplace: matching graph at the F1-max threshold (0.001744), top view'
set xlabel 'x [m]'
set ylabel 'y [m]'
set xtics 50
set ytics -50, 50
set grid
set size ratio -1
set key outside right top vertical Left reverse box
set key title 'F1-max threshold: d ≤ 0.001744'
plot 'graphxy_campus__raplace.csv' skip 1 index 0 using 1:2 with lines lw 1 dt 1 lc rgb '#404040' title 'trajectory', \
      'graphxy_campus__raplace.csv' skip 1 index 1 using 1:2:4:5 with vectors nohead lw 0.8 lc rgb '#a01a9641' title 'TP (357)', \
      'graphxy_campus__raplace.csv' skip 1 index 2 using 1:2:4:5 with vectors nohead lw 1.5 lc rgb '#d7191c' title 'FP (1)'
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,640 font 'sans,11' background rgb 'white' noenhanced
} else {
  set terminal png size 1200,640 background rgb 'white' noenhanced
}
set output 'graphxy_campus__raplace.png'
replot
# A gnuplot without cairo draws no PDF (the SVG and PNG are there).
if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {
  set terminal pdfcairo size 12in,6.4in font 'sans,10' fontscale 1 noenhanced
  set output 'graphxy_campus__raplace.pdf'
  replot
}
unset output
