# radarpr figure (screen style): ROC AUC against descriptor size.
# Run `gnuplot auc_vs_size.gp` in this folder: it reads auc_vs_size.csv (blocks separated by two
# blank lines, selected with `index`) and writes auc_vs_size.svg, auc_vs_size.png and auc_vs_size.pdf.
set datafile separator comma
set terminal svg size 1200,640 font 'sans,12' background rgb 'white' noenhanced
set output 'auc_vs_size.svg'
set title 'ROC AUC against descriptor payload size: per session kind, the mean over its datasets'
set logscale x
set xrange [66.66666666666667:393216]
set yrange [0.65:1.05]
set xlabel 'payload bytes (log scale)'
set ylabel 'mean ROC AUC'
set key outside right top vertical Left reverse box
set grid
plot 'auc_vs_size.csv' skip 1 index 0 using 1:2 with points pt 7 ps 1.8 lc rgb '#0072b2' title 'RadarSC', \
     'auc_vs_size.csv' skip 1 index 1 using 1:2 with points pt 4 ps 2.6 lw 2 lc rgb '#0072b2' notitle, \
     'auc_vs_size.csv' skip 1 index 2 using 1:2 with points pt 7 ps 1.8 lc rgb '#d55e00' title 'Raplace', \
     'auc_vs_size.csv' skip 1 index 3 using 1:2 with points pt 4 ps 2.6 lw 2 lc rgb '#d55e00' notitle, \
     'auc_vs_size.csv' skip 1 index 4 using 1:2 with points pt 7 ps 1.8 lc rgb '#009e73' title 'RadVLAD', \
     'auc_vs_size.csv' skip 1 index 5 using 1:2 with points pt 4 ps 2.6 lw 2 lc rgb '#009e73' notitle, \
     'auc_vs_size.csv' skip 1 index 6 using 1:2 with points pt 7 ps 1.8 lc rgb '#cc79a7' title 'RadarSC-DS', \
     'auc_vs_size.csv' skip 1 index 7 using 1:2 with points pt 4 ps 2.6 lw 2 lc rgb '#cc79a7' notitle, \
     'auc_vs_size.csv' skip 1 index 8 using 1:2 with points pt 7 ps 1.8 lc rgb '#e69f00' title 'Raplace-DS', \
     'auc_vs_size.csv' skip 1 index 9 using 1:2 with points pt 4 ps 2.6 lw 2 lc rgb '#e69f00' notitle, \
     'auc_vs_size.csv' skip 1 index 10 using 1:2 with points pt 7 ps 1.8 lc rgb '#56b4e9' title 'RadVLAD-DS', \
     'auc_vs_size.csv' skip 1 index 11 using 1:2 with points pt 4 ps 2.6 lw 2 lc rgb '#56b4e9' notitle, \
     'auc_vs_size.csv' skip 1 index 12 using 1:2 with points pt 7 ps 1.8 lc rgb '#882255' title 'ReFeree', \
     'auc_vs_size.csv' skip 1 index 13 using 1:2 with points pt 4 ps 2.6 lw 2 lc rgb '#882255' notitle, \
     NaN with points pt 7 ps 1.8 lc rgb 'black' title 'single session (mean over datasets)', \
     NaN with points pt 4 ps 2.6 lw 2 lc rgb 'black' title 'multi session (mean over datasets)'
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,640 font 'sans,11' background rgb 'white' noenhanced
} else {
  set terminal png size 1200,640 background rgb 'white' noenhanced
}
set output 'auc_vs_size.png'
replot
# A gnuplot without cairo draws no PDF (the SVG and PNG are there).
if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {
  set terminal pdfcairo size 12in,6.4in font 'sans,10' fontscale 1 noenhanced
  set output 'auc_vs_size.pdf'
  replot
}
unset output
