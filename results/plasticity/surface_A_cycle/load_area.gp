# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots from curves.csv.
set datafile separator ','
set datafile missing ''
set terminal pngcairo noenhanced size 1400,600 font ',11'
set output '.load_area.png.partial'
set multiplot layout 1,2 title "plasticity_A_cycle: real contact area against load"
unset logscale
set key top left
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'bem_path.csv' using 2:4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference) (load path)', \
     'bem_elastic_path.csv' using 2:4 with linespoints lw 1.5 title 'bem_elastic (load path) (elastic: ignores hardness)'
set logscale xy
set key bottom right
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'bem_path.csv' using 2:4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference) (load path)', \
     'bem_elastic_path.csv' using 2:4 with linespoints lw 1.5 title 'bem_elastic (load path) (elastic: ignores hardness)'
unset multiplot
set terminal svg noenhanced size 1400,600 dynamic font ',11'
set output '.load_area.svg.partial'
set multiplot layout 1,2 title "plasticity_A_cycle: real contact area against load"
unset logscale
set key top left
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'bem_path.csv' using 2:4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference) (load path)', \
     'bem_elastic_path.csv' using 2:4 with linespoints lw 1.5 title 'bem_elastic (load path) (elastic: ignores hardness)'
set logscale xy
set key bottom right
set xlabel 'P/(E* A0)'
set ylabel 'A/A0'
set grid
plot 'bem_path.csv' using 2:4 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title 'bem (reference) (load path)', \
     'bem_elastic_path.csv' using 2:4 with linespoints lw 1.5 title 'bem_elastic (load path) (elastic: ignores hardness)'
unset multiplot
unset output
