# radarpr figure (screen style): town: ROC AUC over the 30 pairs, one box per descriptor (median, quartiles, whiskers to 1.5 IQR; undefined values left out).
# Run `gnuplot matrix_town__box__roc_auc.gp` in this folder: it reads matrix_town__box__roc_auc.csv (blocks separated by two
# blank lines, selected with `index`) and writes matrix_town__box__roc_auc.svg, matrix_town__box__roc_auc.png and matrix_town__box__roc_auc.pdf.
set datafile separator comma
set terminal svg size 750,564 font 'sans,12' background rgb 'white' noenhanced
set output 'matrix_town__box__roc_auc.svg'
set title 'town: ROC AUC per pair'
set ylabel 'ROC AUC'
set yrange [0:1]
set xrange [-0.6:2.6]
set xtics ('referee' 0, 'referee_r' 1, 'open_radvlad:'."\n".'bin_dim=128,'."\n".'clusters=16,'."\n".'max_iterations=10' 2)
set bmargin 6
set style fill solid 0.35 border -1
set style boxplot outliers pointtype 7
set boxwidth 0.5
set grid ytics
plot for [i=0:2] 'matrix_town__box__roc_auc.csv' using (i):($1 == i ? $2 : NaN):(0.5) skip 1 with boxplot lc rgb '#0072b2' notitle
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 750,564 font 'sans,11' background rgb 'white' noenhanced
} else {
  set terminal png size 750,564 background rgb 'white' noenhanced
}
set output 'matrix_town__box__roc_auc.png'
replot
# A gnuplot without cairo draws no PDF (the SVG and PNG are there).
if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {
  set terminal pdfcairo size 7.5in,5.64in font 'sans,10' fontscale 1 noenhanced
  set output 'matrix_town__box__roc_auc.pdf'
  replot
}
unset output
