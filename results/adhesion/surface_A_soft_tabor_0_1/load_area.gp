# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots from curves.csv.
set datafile separator ','
set datafile missing ''
set terminal pngcairo noenhanced size 1400,600 font ',11'
set output '.load_area.png.partial'
set multiplot layout 1,2 title "adhesion_A_soft_tabor_0_1: real contact area against load"
unset logscale
set key top left
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference)', \
     'curves.csv' using (strcol(1) eq 'bem_non_adhesive' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_non_adhesive (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz (Hertz-consistent plateaus, this project; non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'fuller_tabor' ? $3 : NaN):4 with linespoints lw 1.5 title 'fuller_tabor (GW summits each a JKR sphere)', \
     'curves.csv' using (strcol(1) eq 'maugis_gw' ? $3 : NaN):4 with linespoints lw 1.5 title 'maugis_gw (GW summits each a Maugis-Dugdale sphere)', \
     'curves.csv' using (strcol(1) eq 'maugis_gw_retract' ? $3 : NaN):4 with linespoints lw 1.5 title 'maugis_gw_retract (GW summits each a Maugis-Dugdale sphere)', \
     'curves.csv' using (strcol(1) eq 'plateau_kendall' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_kendall (plateaus as Kendall punches, this project)', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz_jkr' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz_jkr (Hertz-consistent plateaus as JKR contacts, this project)'
set logscale xy
set key bottom right
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference)', \
     'curves.csv' using (strcol(1) eq 'bem_non_adhesive' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_non_adhesive (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz (Hertz-consistent plateaus, this project; non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'fuller_tabor' ? $3 : NaN):4 with linespoints lw 1.5 title 'fuller_tabor (GW summits each a JKR sphere)', \
     'curves.csv' using (strcol(1) eq 'maugis_gw' ? $3 : NaN):4 with linespoints lw 1.5 title 'maugis_gw (GW summits each a Maugis-Dugdale sphere)', \
     'curves.csv' using (strcol(1) eq 'maugis_gw_retract' ? $3 : NaN):4 with linespoints lw 1.5 title 'maugis_gw_retract (GW summits each a Maugis-Dugdale sphere)', \
     'curves.csv' using (strcol(1) eq 'plateau_kendall' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_kendall (plateaus as Kendall punches, this project)', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz_jkr' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz_jkr (Hertz-consistent plateaus as JKR contacts, this project)'
unset multiplot
set terminal svg noenhanced size 1400,600 dynamic font ',11'
set output '.load_area.svg.partial'
set multiplot layout 1,2 title "adhesion_A_soft_tabor_0_1: real contact area against load"
unset logscale
set key top left
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference)', \
     'curves.csv' using (strcol(1) eq 'bem_non_adhesive' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_non_adhesive (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz (Hertz-consistent plateaus, this project; non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'fuller_tabor' ? $3 : NaN):4 with linespoints lw 1.5 title 'fuller_tabor (GW summits each a JKR sphere)', \
     'curves.csv' using (strcol(1) eq 'maugis_gw' ? $3 : NaN):4 with linespoints lw 1.5 title 'maugis_gw (GW summits each a Maugis-Dugdale sphere)', \
     'curves.csv' using (strcol(1) eq 'maugis_gw_retract' ? $3 : NaN):4 with linespoints lw 1.5 title 'maugis_gw_retract (GW summits each a Maugis-Dugdale sphere)', \
     'curves.csv' using (strcol(1) eq 'plateau_kendall' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_kendall (plateaus as Kendall punches, this project)', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz_jkr' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz_jkr (Hertz-consistent plateaus as JKR contacts, this project)'
set logscale xy
set key bottom right
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'curves.csv' using (strcol(1) eq 'bem' ? $3 : NaN):4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference)', \
     'curves.csv' using (strcol(1) eq 'bem_non_adhesive' ? $3 : NaN):4 with linespoints lw 1.5 title 'bem_non_adhesive (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz (Hertz-consistent plateaus, this project; non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'persson' ? $3 : NaN):4 with linespoints lw 1.5 title 'persson (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'gw_mccool' ? $3 : NaN):4 with linespoints lw 1.5 title 'gw_mccool (non-adhesive: ignores adhesion)', \
     'curves.csv' using (strcol(1) eq 'fuller_tabor' ? $3 : NaN):4 with linespoints lw 1.5 title 'fuller_tabor (GW summits each a JKR sphere)', \
     'curves.csv' using (strcol(1) eq 'maugis_gw' ? $3 : NaN):4 with linespoints lw 1.5 title 'maugis_gw (GW summits each a Maugis-Dugdale sphere)', \
     'curves.csv' using (strcol(1) eq 'maugis_gw_retract' ? $3 : NaN):4 with linespoints lw 1.5 title 'maugis_gw_retract (GW summits each a Maugis-Dugdale sphere)', \
     'curves.csv' using (strcol(1) eq 'plateau_kendall' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_kendall (plateaus as Kendall punches, this project)', \
     'curves.csv' using (strcol(1) eq 'plateau_hertz_jkr' ? $3 : NaN):4 with linespoints lw 1.5 title 'plateau_hertz_jkr (Hertz-consistent plateaus as JKR contacts, this project)'
unset multiplot
unset output
