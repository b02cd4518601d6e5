# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots from curves.csv.
set datafile separator ','
set datafile missing ''
set terminal pngcairo noenhanced size 1400,600 font ',11'
set output '.load_area.png.partial'
set multiplot layout 1,2 title "accuracy_vs_time: real contact area against load"
unset logscale
set key top left
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem_2048_1e-10' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem_2048_1e-10 (reference)', \
     'curves.csv' using (strcol(1) eq 'bem_256_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_256_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_1024_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_1024_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-4' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-4', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-6' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-6', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-10' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-10', \
     'curves.csv' using (strcol(1) eq 'plateau_exact' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_exact', \
     'curves.csv' using (strcol(1) eq 'plateau_500' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_500', \
     'curves.csv' using (strcol(1) eq 'plateau_100' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_100', \
     'curves.csv' using (strcol(1) eq 'bem_x_256' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_x_256', \
     'curves.csv' using (strcol(1) eq 'bem_x_512' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_x_512', \
     'curves.csv' using (strcol(1) eq 'plateau_1024' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_1024', \
     'curves.csv' using (strcol(1) eq 'plateau_2048' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_2048', \
     'curves.csv' using (strcol(1) eq 'hertz_256' ? $3 : NaN):4 with linespoints lw 1.5 title 'hertz_256 (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'hertz_1024' ? $3 : NaN):4 with linespoints lw 1.5 title 'hertz_1024 (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool', \
     'curves.csv' using (strcol(1) eq 'bgt' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt', \
     'curves.csv' using (strcol(1) eq 'bgt_linear' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt_linear', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson'
set logscale xy
set key bottom right
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem_2048_1e-10' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem_2048_1e-10 (reference)', \
     'curves.csv' using (strcol(1) eq 'bem_256_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_256_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_1024_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_1024_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-4' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-4', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-6' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-6', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-10' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-10', \
     'curves.csv' using (strcol(1) eq 'plateau_exact' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_exact', \
     'curves.csv' using (strcol(1) eq 'plateau_500' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_500', \
     'curves.csv' using (strcol(1) eq 'plateau_100' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_100', \
     'curves.csv' using (strcol(1) eq 'bem_x_256' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_x_256', \
     'curves.csv' using (strcol(1) eq 'bem_x_512' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_x_512', \
     'curves.csv' using (strcol(1) eq 'plateau_1024' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_1024', \
     'curves.csv' using (strcol(1) eq 'plateau_2048' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_2048', \
     'curves.csv' using (strcol(1) eq 'hertz_256' ? $3 : NaN):4 with linespoints lw 1.5 title 'hertz_256 (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'hertz_1024' ? $3 : NaN):4 with linespoints lw 1.5 title 'hertz_1024 (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool', \
     'curves.csv' using (strcol(1) eq 'bgt' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt', \
     'curves.csv' using (strcol(1) eq 'bgt_linear' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt_linear', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson'
unset multiplot
set terminal svg noenhanced size 1400,600 dynamic font ',11'
set output '.load_area.svg.partial'
set multiplot layout 1,2 title "accuracy_vs_time: real contact area against load"
unset logscale
set key top left
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem_2048_1e-10' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem_2048_1e-10 (reference)', \
     'curves.csv' using (strcol(1) eq 'bem_256_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_256_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_1024_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_1024_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-4' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-4', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-6' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-6', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-10' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-10', \
     'curves.csv' using (strcol(1) eq 'plateau_exact' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_exact', \
     'curves.csv' using (strcol(1) eq 'plateau_500' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_500', \
     'curves.csv' using (strcol(1) eq 'plateau_100' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_100', \
     'curves.csv' using (strcol(1) eq 'bem_x_256' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_x_256', \
     'curves.csv' using (strcol(1) eq 'bem_x_512' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_x_512', \
     'curves.csv' using (strcol(1) eq 'plateau_1024' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_1024', \
     'curves.csv' using (strcol(1) eq 'plateau_2048' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_2048', \
     'curves.csv' using (strcol(1) eq 'hertz_256' ? $3 : NaN):4 with linespoints lw 1.5 title 'hertz_256 (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'hertz_1024' ? $3 : NaN):4 with linespoints lw 1.5 title 'hertz_1024 (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool', \
     'curves.csv' using (strcol(1) eq 'bgt' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt', \
     'curves.csv' using (strcol(1) eq 'bgt_linear' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt_linear', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson'
set logscale xy
set key bottom right
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem_2048_1e-10' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem_2048_1e-10 (reference)', \
     'curves.csv' using (strcol(1) eq 'bem_256_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_256_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_1024_1e-8' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_1024_1e-8', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-4' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-4', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-6' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-6', \
     'curves.csv' using (strcol(1) eq 'bem_512_1e-10' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_512_1e-10', \
     'curves.csv' using (strcol(1) eq 'plateau_exact' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_exact', \
     'curves.csv' using (strcol(1) eq 'plateau_500' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_500', \
     'curves.csv' using (strcol(1) eq 'plateau_100' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_100', \
     'curves.csv' using (strcol(1) eq 'bem_x_256' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_x_256', \
     'curves.csv' using (strcol(1) eq 'bem_x_512' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_x_512', \
     'curves.csv' using (strcol(1) eq 'plateau_1024' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_1024', \
     'curves.csv' using (strcol(1) eq 'plateau_2048' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_2048', \
     'curves.csv' using (strcol(1) eq 'hertz_256' ? $3 : NaN):4 with linespoints lw 1.5 title 'hertz_256 (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'hertz_1024' ? $3 : NaN):4 with linespoints lw 1.5 title 'hertz_1024 (Hertz-consistent plateaus, this project)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool', \
     'curves.csv' using (strcol(1) eq 'bgt' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt', \
     'curves.csv' using (strcol(1) eq 'bgt_linear' ? $3 : NaN):4 with linespoints lw 1.5 title 'bgt_linear', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson'
unset multiplot
unset output
