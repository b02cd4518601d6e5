# Made by scripts/studies/resolution.py: `gnuplot kappa.gp` in this folder redraws the plot from kappa.csv.
set datafile separator ','
set termoption noenhanced
set xlabel 'pixel size dx [um] (200 um / points a side)'
set ylabel 'areal kappa at P/(E* A0) = 0.0001'
set logscale x
set xrange [0.07:1]
set yrange [1.5:4.6]
set grid
set key outside right
set title 'Surface A: kappa against pixel size (the same surface, Fourier-refined)'
set object 1 rect from graph 0, first 2.386381107763008 to graph 1, first 2.4070759149773955 fc rgb '#dddddd' fs solid 0.5 noborder behind
do for [t in "pngcairo svg"] {
  if (t eq "pngcairo") { set terminal pngcairo noenhanced size 1300,650 font ',11'; set output 'kappa.png' }
  else { set terminal svg noenhanced size 1300,650 dynamic font ',11'; set output 'kappa.svg' }
  plot 2.3967285113702017 with lines lw 1 dt 2 lc rgb 'black' title 'reference (BEM extrapolated 1024/2048) and its error bar', \
       2.5066282746310007 with lines lw 1 dt 3 lc rgb '#d62728' title 'bgt_linear (grid-independent)', \
       1.5957686373923834 with lines lw 1 dt 4 lc rgb '#9467bd' title 'persson (grid-independent)', \
       'kappa.csv' using (strcol(1) eq 'BEM nodes' ? $3 : NaN):4 with linespoints lw 2 pt 5 title 'BEM nodes', \
       'kappa.csv' using (strcol(1) eq 'BEM corrected' ? $3 : NaN):4 with linespoints lw 2 pt 6 title 'BEM corrected', \
       'kappa.csv' using (strcol(1) eq 'BEM extrapolated from n/2 and n' ? $3 : NaN):4 with linespoints lw 2 pt 7 title 'BEM extrapolated from n/2 and n', \
       'kappa.csv' using (strcol(1) eq 'plateau 4' ? $3 : NaN):4 with linespoints lw 2 pt 8 title 'plateau 4', \
       'kappa.csv' using (strcol(1) eq 'plateau 8' ? $3 : NaN):4 with linespoints lw 2 pt 9 title 'plateau 8', \
       'kappa.csv' using (strcol(1) eq 'Hertz-consistent plateaus 4 (this project)' ? $3 : NaN):4 with linespoints lw 2 pt 10 title 'Hertz-consistent plateaus 4 (this project)'
}
unset output
