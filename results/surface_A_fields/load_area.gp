# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots; the data blocks below are the curves of curves.csv (load, A/A0, A/A0 -+ its error estimate,
# A/A_ref - 1, the reference's relative error estimate).
$method0 << EOD
0.001 0.014172033560717511 NaN NaN 0 NaN
0.005 0.06897985359995527 NaN NaN 0 NaN
0.02 0.2560018687572619 NaN NaN 0 NaN
EOD
set terminal pngcairo enhanced size 1400,1000 font ',11'
set output '.load_area.png.partial'
set multiplot layout 2,2 title 'surface_A_fields: real contact area against load' noenhanced
set key off
set grid
set border
set tics
set lmargin -1
set rmargin -1
set xlabel '{/:Italic P} / ({/:Italic E}^*{/:Italic A}_0)'
unset logscale
set format x '%g'
set format y '%g'
set title '(a) linear axes'
set ylabel '{/:Italic A} / {/:Italic A}_0'
set xrange [0:0.0206]
set yrange [0:0.268801962195125]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set title '(b) logarithmic axes'
set xrange [0.0007936507936507937:0.0252]
set yrange [0.011247645683109136:0.32256235463415]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle
set logscale x
unset logscale y
set format y '%g'
set yrange [*:*]
set title '(c) relative error against the reference'
set ylabel '{/:Italic A} / {/:Italic A}_{ref} - 1'
plot 0 with lines lw 1 lc rgb 'black' dt 2 notitle
unset title
set border 0
unset tics
unset xlabel
unset ylabel
unset logscale
unset grid
set lmargin 0
set rmargin 0
set xrange [0:1]
set yrange [0:1]
set key inside left center vertical Left reverse noautotitle spacing 1.4 width 2
plot 2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title "bem (reference)" noenhanced
unset multiplot
set terminal svg enhanced size 1400,1000 dynamic font ',11'
set output '.load_area.svg.partial'
set multiplot layout 2,2 title 'surface_A_fields: real contact area against load' noenhanced
set key off
set grid
set border
set tics
set lmargin -1
set rmargin -1
set xlabel '{/:Italic P} / ({/:Italic E}^*{/:Italic A}_0)'
unset logscale
set format x '%g'
set format y '%g'
set title '(a) linear axes'
set ylabel '{/:Italic A} / {/:Italic A}_0'
set xrange [0:0.0206]
set yrange [0:0.268801962195125]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set title '(b) logarithmic axes'
set xrange [0.0007936507936507937:0.0252]
set yrange [0.011247645683109136:0.32256235463415]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle
set logscale x
unset logscale y
set format y '%g'
set yrange [*:*]
set title '(c) relative error against the reference'
set ylabel '{/:Italic A} / {/:Italic A}_{ref} - 1'
plot 0 with lines lw 1 lc rgb 'black' dt 2 notitle
unset title
set border 0
unset tics
unset xlabel
unset ylabel
unset logscale
unset grid
set lmargin 0
set rmargin 0
set xrange [0:1]
set yrange [0:1]
set key inside left center vertical Left reverse noautotitle spacing 1.4 width 2
plot 2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title "bem (reference)" noenhanced
unset multiplot
unset output
