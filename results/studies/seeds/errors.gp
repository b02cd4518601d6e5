# Made by scripts/studies/seeds.py: `gnuplot errors.gp` in this folder redraws from errors.csv.
set datafile separator ','
set termoption noenhanced
fam(s) = s eq 'A' ? 0 : s eq 'B' ? 1 : s eq 'H03' ? 2 : s eq 'H09' ? 3 : s eq 'narrow_qs' ? 4 : s eq 'narrow_qr' ? 5 : s eq 'measured' ? 6 : NaN
set xtics ('A' 0, 'B' 1, 'H03' 2, 'H09' 3, 'narrow_qs' 4, 'narrow_qr' 5, 'measured' 6)
set xrange [-0.6:6.6]
set ylabel 'error in A/A0 against the BEM at P/(E* A0) = 0.005 [%] (mean ± sd over realisations)'
set grid ytics
set key outside right
set title 'Every method against the BEM, over seeds and surface families'
do for [t in "pngcairo svg"] {
  if (t eq "pngcairo") { set terminal pngcairo noenhanced size 1400,650 font ',11'; set output 'errors.png' }
  else { set terminal svg noenhanced size 1400,650 dynamic font ',11'; set output 'errors.svg' }
  plot 0 with lines lc rgb 'black' notitle, \
       'errors.csv' using (fam(strcol(1)) + -0.30000000000000004):(strcol(2) eq 'plateau_256' && $3 == 0.005 ? 100*$4 : NaN):(100*$5) with yerrorbars pt 5 ps 1.3 lw 2 title 'plateau model, 256 (as the paper)', \
       'errors.csv' using (fam(strcol(1)) + -0.2):(strcol(2) eq 'plateau_1024' && $3 == 0.005 ? 100*$4 : NaN):(100*$5) with yerrorbars pt 6 ps 1.3 lw 2 title 'plateau model, 1024 (converged)', \
       'errors.csv' using (fam(strcol(1)) + -0.1):(strcol(2) eq 'hertz_1024' && $3 == 0.005 ? 100*$4 : NaN):(100*$5) with yerrorbars pt 7 ps 1.3 lw 2 title 'Hertz-consistent plateaus, 1024 (this project)', \
       'errors.csv' using (fam(strcol(1)) + 0.0):(strcol(2) eq 'bem_256' && $3 == 0.005 ? 100*$4 : NaN):(100*$5) with yerrorbars pt 8 ps 1.3 lw 2 title 'BEM 256, perimeter-corrected', \
       'errors.csv' using (fam(strcol(1)) + 0.1):(strcol(2) eq 'bgt_linear' && $3 == 0.005 ? 100*$4 : NaN):(100*$5) with yerrorbars pt 9 ps 1.3 lw 2 title 'bgt_linear', \
       'errors.csv' using (fam(strcol(1)) + 0.2):(strcol(2) eq 'persson' && $3 == 0.005 ? 100*$4 : NaN):(100*$5) with yerrorbars pt 10 ps 1.3 lw 2 title 'persson'
}
unset output
