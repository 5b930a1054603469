# radarpr figure (screen style): ROC AUC against descriptor size.
# Run `gnuplot auc_vs_size.gp` in this folder: it reads auc_vs_size.csv (blocks separated by two
# blank lines, selected with `index`) and writes auc_vs_size.svg, auc_vs_size.png and auc_vs_size.pdf.
set datafile separator comma
set terminal svg size 1200,640 font 'sans,12' background rgb 'white' noenhanced
set output 'auc_vs_size.svg'
set title 'ROC AUC against descriptor payload size: per session kind, the mean over its datasets'
set logscale x
set xrange [66.66666666666667:393216]
set yrange [0.65:1]
set xtics ("10²" 100, "2" 200, "5" 500, "10³" 1000, "2" 2000, "5" 5000, "10⁴" 10000, "2" 20000, "5" 50000, "10⁵" 100000, "2" 200000)
set xlabel 'payload bytes (log scale)'
set ylabel 'mean ROC AUC'
set key outside right top vertical Left reverse box
set grid xtics mxtics ytics
set label 10 'RadarSC' at 4800,0.8184570160685593 offset char 0.9,0.4 left font ',10' textcolor rgb '#0072b2' front
set label 11 'RadarSC' at 4800,0.959734926943669 offset char 0.9,0.4 left font ',10' textcolor rgb '#0072b2' front
set label 12 'Raplace' at 1440,0.9991664051352863 offset char 0.9,-0.6 left font ',10' textcolor rgb '#d55e00' front
set label 13 'Raplace' at 1440,0.913145456771386 offset char 0.9,0.4 left font ',10' textcolor rgb '#d55e00' front
set label 14 'RadVLAD' at 131072,0.8952652279841725 offset char 0.9,0.4 left font ',10' textcolor rgb '#009e73' front
set label 15 'RadVLAD' at 131072,0.9597125984807735 offset char 0.9,0.4 left font ',10' textcolor rgb '#009e73' front
set label 16 'RadarSC-DS' at 200,0.9589852289277832 offset char 0.9,0.4 left font ',10' textcolor rgb '#cc79a7' front
set label 17 'RadarSC-DS' at 200,0.9144765035695523 offset char 0.9,0.4 left font ',10' textcolor rgb '#cc79a7' front
set label 18 'Raplace-DS' at 224,0.9878241971872157 offset char 0.9,0.4 left font ',10' textcolor rgb '#e69f00' front
set label 19 'Raplace-DS' at 224,0.8683517191317928 offset char 0.9,0.4 left font ',10' textcolor rgb '#e69f00' front
set label 20 'RadVLAD-DS' at 2560,0.8206891848892953 offset char -0.9,0.4 right font ',10' textcolor rgb '#56b4e9' front
set label 21 'RadVLAD-DS' at 2560,0.7053528902520504 offset char 0.9,0.4 left font ',10' textcolor rgb '#56b4e9' front
set label 22 'ReFeree' at 200,0.8874007569286287 offset char 0.9,0.4 left font ',10' textcolor rgb '#882255' front
set label 23 'ReFeree' at 200,0.7869107383423072 offset char 0.9,0.4 left font ',10' textcolor rgb '#882255' front
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
