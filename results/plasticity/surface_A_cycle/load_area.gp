# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots; the data blocks below are the curves of curves.csv (load, A/A0, A/A0 -+ its error estimate,
# A/A_ref - 1, the reference's relative error estimate).
$method0 << EOD
5e-04 0.010388380110686175 NaN NaN 0 NaN
0.001 0.020354459111798555 NaN NaN 0 NaN
0.002 0.041310879425968075 NaN NaN 0 NaN
0.004 0.08135354551028615 NaN NaN 0 NaN
EOD
$path0 << EOD
5e-04 0.010388380110686175
0.001 0.020354459111798555
0.002 0.041310879425968075
0.004 0.08135354551028615
0.002 0.05408101667620676
0.001 0.033167737496792735
5e-04 0.020057878492547122
0.001 0.033167737496792735
0.002 0.05408101667620676
0.004 0.08135354551028615
EOD
$method1 << EOD
5e-04 0.00717743872319377 NaN NaN -0.30908970920205525 NaN
0.001 0.014609362289423397 NaN NaN -0.2822524927250455 NaN
0.002 0.02922378312544386 NaN NaN -0.29258869499946427 NaN
0.004 0.05690576238762482 NaN NaN -0.3005128168577509 NaN
EOD
$path1 << EOD
5e-04 0.00717743872319377
0.001 0.014609362289423397
0.002 0.02922378312544386
0.004 0.05690576238762482
0.002 0.02922378312544386
0.001 0.014609362289423397
5e-04 0.00717743872319377
0.001 0.014609362289423397
0.002 0.02922378312544386
0.004 0.05690576238762482
EOD
set terminal pngcairo enhanced size 1400,1000 font ',11'
set output '.load_area.png.partial'
set multiplot layout 2,2 title 'plasticity_A_cycle: real contact area against load' noenhanced
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
set xrange [0:0.00412]
set yrange [0:0.08542122278580046]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $path0 using 1:2 with lines dt 2 lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $path1 using 1:2 with lines dt 2 lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set title '(b) logarithmic axes'
set xrange [0.0003968253968253968:0.00504]
set yrange [0.005696379939042675:0.10250546734296054]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $path0 using 1:2 with lines dt 2 lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $path1 using 1:2 with lines dt 2 lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle
set logscale x
unset logscale y
set format y '%g'
set yrange [*:*]
set title '(c) relative error against the reference'
set ylabel '{/:Italic A} / {/:Italic A}_{ref} - 1'
plot $method1 using 1:5 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     0 with lines lw 1 lc rgb 'black' dt 2 notitle
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
plot 2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title "bem (reference); dashed: its load path" noenhanced, \
     2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' title "bem_elastic (elastic: ignores hardness); dashed: its load path" noenhanced
unset multiplot
set terminal svg enhanced size 1400,1000 dynamic font ',11'
set output '.load_area.svg.partial'
set multiplot layout 2,2 title 'plasticity_A_cycle: real contact area against load' noenhanced
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
set xrange [0:0.00412]
set yrange [0:0.08542122278580046]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $path0 using 1:2 with lines dt 2 lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $path1 using 1:2 with lines dt 2 lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set title '(b) logarithmic axes'
set xrange [0.0003968253968253968:0.00504]
set yrange [0.005696379939042675:0.10250546734296054]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $path0 using 1:2 with lines dt 2 lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $path1 using 1:2 with lines dt 2 lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle
set logscale x
unset logscale y
set format y '%g'
set yrange [*:*]
set title '(c) relative error against the reference'
set ylabel '{/:Italic A} / {/:Italic A}_{ref} - 1'
plot $method1 using 1:5 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     0 with lines lw 1 lc rgb 'black' dt 2 notitle
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
plot 2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title "bem (reference); dashed: its load path" noenhanced, \
     2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' title "bem_elastic (elastic: ignores hardness); dashed: its load path" noenhanced
unset multiplot
unset output
