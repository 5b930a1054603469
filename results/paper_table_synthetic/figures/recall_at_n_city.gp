# radarpr figure (screen style): Recall@N curves.
# Run `gnuplot recall_at_n_city.gp` in this folder: it reads recall_at_n_city.csv (blocks separated by two
# blank lines, selected with `index`) and writes recall_at_n_city.svg, recall_at_n_city.png and recall_at_n_city.pdf.
set datafile separator comma
set terminal svg size 1200,640 font 'sans,12' background rgb 'white' noenhanced
set output 'recall_at_n_city.svg'
set title 'city: Recall@N, the share of revisit queries with a frame within the revisit radius among their N nearest (N = 1 to 25; Recall@1 as in the tables). Stopping early: RadarSC at N = 5, RadarSC-DS at N = 5; these descriptors re-rank only the candidates their key pre-search hands over (their `candidates` parameter), so a correct frame beyond them is never ranked'
set xlabel 'N (nearest frames retrieved)'
set ylabel 'Recall@N'
set xrange [0.5:25.5]
set yrange [0:1.02]
set xtics 0,5
set xtics add ('1' 1)
set key outside right top vertical Left reverse box
set grid
plot 'recall_at_n_city.csv' skip 1 index 0 using 1:2 with linespoints lw 3 dt 1 pt 4 ps 1.0 lc rgb '#0072b2' title 'RadarSC (ranks end at N = 5)', \
     'recall_at_n_city.csv' skip 1 index 1 using 1:2 with linespoints lw 3 dt 2 pt 6 ps 1.0 lc rgb '#d55e00' title 'Raplace', \
     'recall_at_n_city.csv' skip 1 index 2 using 1:2 with linespoints lw 3 dt 3 pt 8 ps 1.0 lc rgb '#009e73' title 'RadVLAD', \
     'recall_at_n_city.csv' skip 1 index 3 using 1:2 with linespoints lw 3 dt 4 pt 12 ps 1.0 lc rgb '#cc79a7' title 'RadarSC-DS (ranks end at N = 5)', \
     'recall_at_n_city.csv' skip 1 index 4 using 1:2 with linespoints lw 3 dt 5 pt 10 ps 1.0 lc rgb '#e69f00' title 'Raplace-DS', \
     'recall_at_n_city.csv' skip 1 index 5 using 1:2 with linespoints lw 3 dt 1 pt 14 ps 1.0 lc rgb '#56b4e9' title 'RadVLAD-DS', \
     'recall_at_n_city.csv' skip 1 index 6 using 1:2 with linespoints lw 3 dt 2 pt 1 ps 1.0 lc rgb '#882255' title 'ReFeree'
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {
  set terminal pngcairo size 1200,640 font 'sans,11' background rgb 'white' noenhanced
} else {
  set terminal png size 1200,640 background rgb 'white' noenhanced
}
set output 'recall_at_n_city.png'
replot
# A gnuplot without cairo draws no PDF (the SVG and PNG are there).
if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {
  set terminal pdfcairo size 12in,6.4in font 'sans,10' fontscale 1 noenhanced
  set output 'recall_at_n_city.pdf'
  replot
}
unset output
