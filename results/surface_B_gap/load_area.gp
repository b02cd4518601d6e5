# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots from curves.csv.
set datafile separator ','
set datafile missing ''
set terminal pngcairo noenhanced size 1400,600 font ',11'
set output '.load_area.png.partial'
set multiplot layout 1,2 title "surface_B_gap: real contact area against load"
unset logscale
set key top left
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference)', \
     'curves.csv' using (strcol(1) eq 'plateau_4' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_4', \
     'curves.csv' using (strcol(1) eq 'plateau_8' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_8', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool', \
     'curves.csv' using (strcol(1) eq 'bgt' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt', \
     'curves.csv' using (strcol(1) eq 'bgt_linear' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt_linear', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson'
set logscale xy
set key bottom right
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference)', \
     'curves.csv' using (strcol(1) eq 'plateau_4' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_4', \
     'curves.csv' using (strcol(1) eq 'plateau_8' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_8', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool', \
     'curves.csv' using (strcol(1) eq 'bgt' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt', \
     'curves.csv' using (strcol(1) eq 'bgt_linear' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt_linear', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson'
unset multiplot
set terminal svg noenhanced size 1400,600 dynamic font ',11'
set output '.load_area.svg.partial'
set multiplot layout 1,2 title "surface_B_gap: real contact area against load"
unset logscale
set key top left
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference)', \
     'curves.csv' using (strcol(1) eq 'plateau_4' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_4', \
     'curves.csv' using (strcol(1) eq 'plateau_8' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_8', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool', \
     'curves.csv' using (strcol(1) eq 'bgt' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt', \
     'curves.csv' using (strcol(1) eq 'bgt_linear' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt_linear', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson'
set logscale xy
set key bottom right
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference)', \
     'curves.csv' using (strcol(1) eq 'plateau_4' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_4', \
     'curves.csv' using (strcol(1) eq 'plateau_8' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_8', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool', \
     'curves.csv' using (strcol(1) eq 'bgt' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt', \
     'curves.csv' using (strcol(1) eq 'bgt_linear' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt_linear', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson'
unset multiplot
unset output
