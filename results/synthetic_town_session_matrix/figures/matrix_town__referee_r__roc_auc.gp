# radarpr figure (screen style): town, referee_r: ROC AUC per pair (query session down, database session across; blank: not evaluated or undefined).
# Run `gnuplot matrix_town__referee_r__roc_auc.gp` in this folder: it reads matrix_town__referee_r__roc_auc.csv (blocks separated by two
# blank lines, selected with `index`) and writes matrix_town__referee_r__roc_auc.svg, matrix_town__referee_r__roc_auc.png and matrix_town__referee_r__roc_auc.pdf.
set datafile separator comma
set terminal svg size 780,660 font 'sans,12' background rgb 'white' noenhanced
set output 'matrix_town__referee_r__roc_auc.svg'
set title 'town: referee_r, ROC AUC'
set datafile missing 'NaN'
set xlabel 'database session'
set ylabel 'query session'
set xrange [-0.5:5.5]
set yrange [5.5:-0.5]
set xtics ('clear' 0, 'rain' 1, 'snow' 2, 'rush_hour' 3, 'inner_lane' 4, 'parked_moved' 5) rotate by 30 right
set ytics ('clear' 0, 'rain' 1, 'snow' 2, 'rush_hour' 3, 'inner_lane' 4, 'parked_moved' 5)
set cbrange [0:1]
set cblabel 'ROC AUC'
set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', 1 '#fde725')
set size ratio -1
set tics out
plot 'matrix_town__referee_r__roc_auc.csv' using 1:2:(0.5):(0.5):3 skip 1 with boxxyerror fill solid 1.0 noborder lc palette notitle, \
     '' using 1:2:($3 >= 0.6 ? sprintf('%.2f', $3) : '') skip 1 with labels textcolor rgb 'black' notitle, \
     '' using 1:2:($3 < 0.6 ? sprintf('%.2f', $3) : '') skip 1 with labels textcolor rgb 'white' notitle
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 780,660 font 'sans,11' background rgb 'white' noenhanced
} else {
  set terminal png size 780,660 background rgb 'white' noenhanced
}
set output 'matrix_town__referee_r__roc_auc.png'
replot
# A gnuplot without cairo draws no PDF (the SVG and PNG are there).
if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {
  set terminal pdfcairo size 7.8in,6.6in font 'sans,10' fontscale 1 noenhanced
  set output 'matrix_town__referee_r__roc_auc.pdf'
  replot
}
unset output
