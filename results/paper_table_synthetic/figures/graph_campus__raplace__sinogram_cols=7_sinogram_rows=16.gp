# radarpr figure (screen style): matching graph at the F1-max threshold.
# Run `gnuplot graph_campus__raplace__sinogram_cols=7_sinogram_rows=16.gp` in this folder: it reads graph_campus__raplace__sinogram_cols=7_sinogram_rows=16.csv (blocks separated by two
# blank lines, selected with `index`) and writes graph_campus__raplace__sinogram_cols=7_sinogram_rows=16.svg, graph_campus__raplace__sinogram_cols=7_sinogram_rows=16.png and graph_campus__raplace__sinogram_cols=7_sinogram_rows=16.pdf.
set datafile separator comma
set terminal svg size 900,640 font 'sans,12' background rgb 'white' noenhanced
set output 'graph_campus__raplace__sinogram_cols=7_sinogram_rows=16.svg'
set title 'campus, Raplace-DS: matching graph at the F1-max threshold (0.0007502)'
set xlabel 'x [m]'
set ylabel 'y [m]'
set xtics 50
set ytics 0, 50
set grid
set zlabel 'frame' rotate parallel
set view 60, 35
set view equal xy
set ticslevel 0
set xtics offset 0,-0.5
set ytics offset 1,-0.5
set key at screen 0.01, screen 0.93 left top Left reverse box opaque
set key title 'F1-max threshold: d ≤ 0.0007502'
splot 'graph_campus__raplace__sinogram_cols=7_sinogram_rows=16.csv' skip 1 index 0 using 1:2:3 with lines lw 1 dt 1 lc rgb '#404040' title 'trajectory', \
      'graph_campus__raplace__sinogram_cols=7_sinogram_rows=16.csv' skip 1 index 1 using 1:2:3:4:5:6 with vectors nohead lw 0.8 lc rgb '#a01a9641' title 'TP (344)', \
      'graph_campus__raplace__sinogram_cols=7_sinogram_rows=16.csv' skip 1 index 2 using 1:2:3:4:5:6 with vectors nohead lw 1.5 lc rgb '#d7191c' title 'FP (8)'
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 900,640 font 'sans,11' background rgb 'white' noenhanced
} else {
  set terminal png size 900,640 background rgb 'white' noenhanced
}
set output 'graph_campus__raplace__sinogram_cols=7_sinogram_rows=16.png'
replot
# A gnuplot without cairo draws no PDF (the SVG and PNG are there).
if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {
  set terminal pdfcairo size 9in,6.4in font 'sans,10' fontscale 1 noenhanced
  set output 'graph_campus__raplace__sinogram_cols=7_sinogram_rows=16.pdf'
  replot
}
unset output
