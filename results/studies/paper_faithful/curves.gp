# Made by scripts/studies/paper_faithful.py: `gnuplot curves.gp` in this folder redraws from curves.csv.
set datafile separator ','
set datafile missing 'nan'
set termoption noenhanced
set logscale xy
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
set key top left font ',9'
do for [t in "pngcairo svg"] {
  if (t eq "pngcairo") { set terminal pngcairo noenhanced size 1400,600 font ',11'; set output 'curves.png' }
  else { set terminal svg noenhanced size 1400,600 dynamic font ',11'; set output 'curves.svg' }
  set multiplot layout 1,2
set title 'Surface A'
plot 'curves.csv' using (strcol(1) eq 'A' ? $2 : NaN):5:6 with yerrorlines lw 3 pt 7 lc rgb 'black' title 'BEM converged (extrapolated 512/1024, error bar)', \
     '' using (strcol(1) eq 'A' ? $2 : NaN):3 with linespoints lw 2 pt 4 dt 2 lc rgb 'black' title 'FE stand-in: BEM 256 node count', \
     '' using (strcol(1) eq 'A' ? $2 : NaN):4 with linespoints lw 2 pt 5 dt 2 lc rgb '#1f77b4' title 'plateau model as made (256, 500 levels)', \
     '' using (strcol(1) eq 'A' ? $2 : NaN):7 with linespoints lw 2 pt 5 lc rgb '#1f77b4' title 'plateau model converged (2048)', \
     '' using (strcol(1) eq 'A' ? $2 : NaN):8 with linespoints lw 2 pt 9 lc rgb '#2ca02c' title 'Hertz-consistent plateaus 2048 (this project)', \
     '' using (strcol(1) eq 'A' ? $2 : NaN):9 with lines lw 1.5 lc rgb '#d62728' title 'persson'
set title 'Surface B'
plot 'curves.csv' using (strcol(1) eq 'B' ? $2 : NaN):5:6 with yerrorlines lw 3 pt 7 lc rgb 'black' title 'BEM converged (extrapolated 512/1024, error bar)', \
     '' using (strcol(1) eq 'B' ? $2 : NaN):3 with linespoints lw 2 pt 4 dt 2 lc rgb 'black' title 'FE stand-in: BEM 256 node count', \
     '' using (strcol(1) eq 'B' ? $2 : NaN):4 with linespoints lw 2 pt 5 dt 2 lc rgb '#1f77b4' title 'plateau model as made (256, 500 levels)', \
     '' using (strcol(1) eq 'B' ? $2 : NaN):7 with linespoints lw 2 pt 5 lc rgb '#1f77b4' title 'plateau model converged (2048)', \
     '' using (strcol(1) eq 'B' ? $2 : NaN):8 with linespoints lw 2 pt 9 lc rgb '#2ca02c' title 'Hertz-consistent plateaus 2048 (this project)', \
     '' using (strcol(1) eq 'B' ? $2 : NaN):9 with lines lw 1.5 lc rgb '#d62728' title 'persson'
  unset multiplot
}
unset output
