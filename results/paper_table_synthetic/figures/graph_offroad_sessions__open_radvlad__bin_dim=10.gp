# radarpr figure (screen style): matching graph at the F1-max threshold.
# Run `gnuplot graph_offroad_sessions__open_radvlad__bin_dim=10.gp` in this folder: it reads graph_offroad_sessions__open_radvlad__bin_dim=10.csv (blocks separated by two
# blank lines, selected with `index`) and writes graph_offroad_sessions__open_radvlad__bin_dim=10.svg, graph_offroad_sessions__open_radvlad__bin_dim=10.png and graph_offroad_sessions__open_radvlad__bin_dim=10.pdf.
set datafile separator comma
set terminal svg size 900,640 font 'sans,12' background rgb 'white' noenhanced
set output 'graph_offroad_sessions__open_radvlad__bin_dim=10.svg'
set title 'offroad_sessions, RadVLAD-DS: matching graph at the F1-max threshold (1.254)'
set xlabel 'x [m]'
set ylabel 'y [m]'
set xtics 200
set ytics 0, 200
set grid
set zlabel 'frame (database, then query session)' rotate parallel
set view 60, 35
set view equal xy
set ticslevel 0
set xtics offset 0,-0.5
set ytics offset 1,-0.5
set key at screen 0.01, screen 0.93 left top Left reverse box opaque
set key title 'F1-max threshold: d ≤ 1.254'
splot 'graph_offroad_sessions__open_radvlad__bin_dim=10.csv' skip 1 index 0 using 1:2:3 with lines lw 4 lc rgb '#c8c8c8' title 'database trajectory', \
      'graph_offroad_sessions__open_radvlad__bin_dim=10.csv' skip 1 index 1 using 1:2:3 with lines lw 1 dt 2 lc rgb '#404040' title 'query trajectory', \
      'graph_offroad_sessions__open_radvlad__bin_dim=10.csv' skip 1 index 2 using 1:2:3:4:5:6 with vectors nohead lw 0.8 lc rgb '#a01a9641' title 'TP (9)', \
      'graph_offroad_sessions__open_radvlad__bin_dim=10.csv' skip 1 index 3 using 1:2:3:4:5:6 with vectors nohead lw 1.5 lc rgb '#d7191c' title 'FP (15)'
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 900,640 font 'sans,11' background rgb 'white' noenhanced
} else {
  set terminal png size 900,640 background rgb 'white' noenhanced
}
set output 'graph_offroad_sessions__open_radvlad__bin_dim=10.png'
replot
# A gnuplot without cairo draws no PDF (the SVG and PNG are there).
if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {
  set terminal pdfcairo size 9in,6.4in font 'sans,10' fontscale 1 noenhanced
  set output 'graph_offroad_sessions__open_radvlad__bin_dim=10.pdf'
  replot
}
unset output
