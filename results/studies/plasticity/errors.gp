# Made by scripts/studies/plasticity.py: `gnuplot errors.gp` in this folder redraws from mean_errors.csv.
set datafile separator ','
set termoption noenhanced
set logscale xy
set xrange [0.25:12]
set xlabel 'plasticity index psi = (E*/H) sqrt(sigma_s/beta)'
set ylabel 'rms error of A/A0 against the capped BEM [%] (mean over 4 surfaces)'
set grid
set key outside right
set title 'Elastic (dashed) and elastic-plastic (solid) methods against the elastic-perfectly plastic BEM'
do for [t in "pngcairo svg"] {
  if (t eq "pngcairo") { set terminal pngcairo noenhanced size 1300,650 font ',11'; set output 'errors.png' }
  else { set terminal svg noenhanced size 1300,650 dynamic font ',11'; set output 'errors.svg' }
  plot 'mean_errors.csv' using 1:(100*$2) with linespoints lw 2 pt 4 dt 2 title 'BEM, elastic', \
       'mean_errors.csv' using 1:(100*$3) with linespoints lw 2 pt 5 dt 2 title 'plateau (paper), elastic', \
       'mean_errors.csv' using 1:(100*$4) with linespoints lw 2 pt 6 dt 2 title 'plateau_hertz (this project), elastic', \
       'mean_errors.csv' using 1:(100*$5) with linespoints lw 2 pt 7 dt 2 title 'GW-McCool, elastic', \
       'mean_errors.csv' using 1:(100*$6) with linespoints lw 2 pt 8 dt 2 title 'Persson, elastic', \
       'mean_errors.csv' using 1:(100*$7) with linespoints lw 2 pt 9 dt 1 title 'plateau capped at H (this project)', \
       'mean_errors.csv' using 1:(100*$8) with linespoints lw 2 pt 10 dt 1 title 'plateau_hertz capped at H (this project)', \
       'mean_errors.csv' using 1:(100*$9) with linespoints lw 2 pt 11 dt 1 title 'Chang-Etsion-Bogy', \
       'mean_errors.csv' using 1:(100*$10) with linespoints lw 2 pt 12 dt 1 title 'Kogut-Etsion', \
       'mean_errors.csv' using 1:(100*$11) with linespoints lw 2 pt 13 dt 1 title 'Persson with yield', \
       'mean_errors.csv' using 1:(100*$12) with linespoints lw 2 pt 14 dt 1 title 'Majumdar-Bhushan'
}
unset output
