# Made by scripts/studies/error_bar.py: `gnuplot estimate.gp` in this folder redraws from cases.csv.
set datafile separator ','
set termoption noenhanced
set logscale xy
set xlabel 'error bar (estimate) in A/A0'
set ylabel 'true error |value - truth| in A/A0'
set key top left
set grid
set title 'BEM reference: true error against its error bar, grids 64/128/256, truth 1024'
do for [t in "pngcairo svg"] {
  if (t eq "pngcairo") { set terminal pngcairo noenhanced size 900,750 font ',11'; set output 'estimate.png' }
  else { set terminal svg noenhanced size 900,750 dynamic font ',11'; set output 'estimate.svg' }
  plot [1e-6:1] [1e-7:1] x with lines lc rgb 'black' title 'true error = bar', \
       'cases.csv' using (strcol(4) eq 'calibrated3' && strcol(13) eq 'calibration' ? $6 : NaN):11 with points pt 7 ps 0.8 lc rgb '#1f77b4' title 'calibrated3, calibration set', \
       'cases.csv' using (strcol(4) eq 'calibrated3' && strcol(13) eq 'holdout' ? $6 : NaN):11 with points pt 5 ps 0.8 lc rgb '#d62728' title 'calibrated3, hold-out set', \
       'cases.csv' using (strcol(4) eq 'corrected1 n=256' ? $6 : NaN):11 with points pt 4 ps 0.7 lc rgb '#2ca02c' title 'corrected area n=256, one grid (both sets)', \
       'cases.csv' using (strcol(4) eq 'gci3' ? $6 : NaN):11 with points pt 2 ps 0.7 lc rgb '#7f7f7f' title 'gci3 (both sets)'
}
unset output
