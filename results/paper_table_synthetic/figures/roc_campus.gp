# radarpr figure (screen style): ROC curves.
# Run `gnuplot roc_campus.gp` in this folder: it reads roc_campus.csv (blocks separated by two
# blank lines, selected with `index`) and writes roc_campus.svg, roc_campus.png and roc_campus.pdf.
set datafile separator comma
set terminal svg size 1200,640 font 'sans,12' background rgb 'white' noenhanced
set output 'roc_campus.svg'
set title 'campus: ROC'
set xlabel 'false positive rate'
set ylabel 'true positive rate (recall)'
set xrange [0:1]
set yrange [0:1.02]
set size square
set key outside right top vertical Left reverse box
set grid
plot x with lines lw 1.5 dt 2 lc rgb 'gray60' title 'chance', \
     'roc_campus.csv' skip 1 index 0 using 1:2 with linespoints lw 3 dt 1 pt 4 ps 1.2 pi 78 lc rgb '#0072b2' title 'RadarSC (AUC 0.987)', \
     'roc_campus.csv' skip 1 index 1 using 1:2 with linespoints lw 3 dt 2 pt 6 ps 1.2 pi 81 lc rgb '#d55e00' title 'Raplace (AUC 0.999)', \
     'roc_campus.csv' skip 1 index 2 using 1:2 with linespoints lw 3 dt 3 pt 8 ps 1.2 pi 84 lc rgb '#009e73' title 'RadVLAD (AUC 0.982)', \
     'roc_campus.csv' skip 1 index 3 using 1:2 with linespoints lw 3 dt 4 pt 12 ps 1.2 pi 87 lc rgb '#cc79a7' title 'RadarSC-DS (AUC 0.990)', \
     'roc_campus.csv' skip 1 index 4 using 1:2 with linespoints lw 3 dt 5 pt 10 ps 1.2 pi 90 lc rgb '#e69f00' title 'Raplace-DS (AUC 0.993)', \
     'roc_campus.csv' skip 1 index 5 using 1:2 with linespoints lw 3 dt 1 pt 14 ps 1.2 pi 93 lc rgb '#56b4e9' title 'RadVLAD-DS (AUC 0.931)', \
     'roc_campus.csv' skip 1 index 6 using 1:2 with linespoints lw 3 dt 2 pt 1 ps 1.2 pi 96 lc rgb '#882255' title 'ReFeree (AUC 0.930)', \
     'roc_campus.csv' skip 1 index 7 every ::0::0 using 1:2 with points pt 7 ps 1.6 lc rgb '#0072b2' notitle, \
     'roc_campus.csv' skip 1 index 7 every ::1::1 using 1:2 with points pt 7 ps 1.6 lc rgb '#d55e00' notitle, \
     'roc_campus.csv' skip 1 index 7 every ::2::2 using 1:2 with points pt 7 ps 1.6 lc rgb '#009e73' notitle, \
     'roc_campus.csv' skip 1 index 7 every ::3::3 using 1:2 with points pt 7 ps 1.6 lc rgb '#cc79a7' notitle, \
     'roc_campus.csv' skip 1 index 7 every ::4::4 using 1:2 with points pt 7 ps 1.6 lc rgb '#e69f00' notitle, \
     'roc_campus.csv' skip 1 index 7 every ::5::5 using 1:2 with points pt 7 ps 1.6 lc rgb '#56b4e9' notitle, \
     'roc_campus.csv' skip 1 index 7 every ::6::6 using 1:2 with points pt 7 ps 1.6 lc rgb '#882255' notitle, \
     NaN with points pt 7 ps 1.6 lc rgb 'black' title 'F1-max'
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,640 font 'sans,11' background rgb 'white' noenhanced
} else {
  set terminal png size 1200,640 background rgb 'white' noenhanced
}
set output 'roc_campus.png'
replot
# A gnuplot without cairo draws no PDF (the SVG and PNG are there).
if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {
  set terminal pdfcairo size 12in,6.4in font 'sans,10' fontscale 1 noenhanced
  set output 'roc_campus.pdf'
  replot
}
unset output
