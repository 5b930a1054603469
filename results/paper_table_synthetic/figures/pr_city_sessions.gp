# radarpr figure (screen style): precision-recall curves.
# Run `gnuplot pr_city_sessions.gp` in this folder: it reads pr_city_sessions.csv (blocks separated by two
# blank lines, selected with `index`) and writes pr_city_sessions.svg, pr_city_sessions.png and pr_city_sessions.pdf.
set datafile separator comma
set terminal svg size 1200,640 font 'sans,12' background rgb 'white' noenhanced
set output 'pr_city_sessions.svg'
set title 'city_sessions: precision-recall'
set xlabel 'recall'
set ylabel 'precision'
set xrange [0:1]
set yrange [0:1.02]
set key outside right top vertical Left reverse box
set grid
plot 'pr_city_sessions.csv' skip 1 index 0 using 1:2 with linespoints lw 3 dt 1 pt 4 ps 1.2 pi 42 lc rgb '#0072b2' title 'RadarSC (F1-max 0.917)', \
     'pr_city_sessions.csv' skip 1 index 1 using 1:2 with linespoints lw 3 dt 2 pt 6 ps 1.2 pi 45 lc rgb '#d55e00' title 'Raplace (F1-max 0.878)', \
     'pr_city_sessions.csv' skip 1 index 2 using 1:2 with linespoints lw 3 dt 3 pt 8 ps 1.2 pi 48 lc rgb '#009e73' title 'RadVLAD (F1-max 0.938)', \
     'pr_city_sessions.csv' skip 1 index 3 using 1:2 with linespoints lw 3 dt 4 pt 12 ps 1.2 pi 49 lc rgb '#cc79a7' title 'RadarSC-DS (F1-max 0.691)', \
     'pr_city_sessions.csv' skip 1 index 4 using 1:2 with linespoints lw 3 dt 5 pt 10 ps 1.2 pi 54 lc rgb '#e69f00' title 'Raplace-DS (F1-max 0.809)', \
     'pr_city_sessions.csv' skip 1 index 5 using 1:2 with linespoints lw 3 dt 1 pt 14 ps 1.2 pi 54 lc rgb '#56b4e9' title 'RadVLAD-DS (F1-max 0.555)', \
     'pr_city_sessions.csv' skip 1 index 6 using 1:2 with linespoints lw 3 dt 2 pt 1 ps 1.2 pi 59 lc rgb '#882255' title 'ReFeree (F1-max 0.797)', \
     'pr_city_sessions.csv' skip 1 index 7 every ::0::0 using 1:2 with points pt 7 ps 1.6 lc rgb '#0072b2' notitle, \
     'pr_city_sessions.csv' skip 1 index 7 every ::1::1 using 1:2 with points pt 7 ps 1.6 lc rgb '#d55e00' notitle, \
     'pr_city_sessions.csv' skip 1 index 7 every ::2::2 using 1:2 with points pt 7 ps 1.6 lc rgb '#009e73' notitle, \
     'pr_city_sessions.csv' skip 1 index 7 every ::3::3 using 1:2 with points pt 7 ps 1.6 lc rgb '#cc79a7' notitle, \
     'pr_city_sessions.csv' skip 1 index 7 every ::4::4 using 1:2 with points pt 7 ps 1.6 lc rgb '#e69f00' notitle, \
     'pr_city_sessions.csv' skip 1 index 7 every ::5::5 using 1:2 with points pt 7 ps 1.6 lc rgb '#56b4e9' notitle, \
     'pr_city_sessions.csv' skip 1 index 7 every ::6::6 using 1:2 with points pt 7 ps 1.6 lc rgb '#882255' notitle, \
     NaN with points pt 7 ps 1.6 lc rgb 'black' title 'F1-max'
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,640 font 'sans,11' background rgb 'white' noenhanced
} else {
  set terminal png size 1200,640 background rgb 'white' noenhanced
}
set output 'pr_city_sessions.png'
replot
# A gnuplot without cairo draws no PDF (the SVG and PNG are there).
if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {
  set terminal pdfcairo size 12in,6.4in font 'sans,10' fontscale 1 noenhanced
  set output 'pr_city_sessions.pdf'
  replot
}
unset output
