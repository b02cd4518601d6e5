# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots; the data blocks below are the curves of curves.csv (load, A/A0, A/A0 -+ its error estimate,
# A/A_ref - 1, the reference's relative error estimate).
$method0 << EOD
0.001 0.010211033571276895 0.008073431493797554 0.012348635648756236 0 0.20934238072552272
0.01 0.09755003733867519 0.08081775073878301 0.11428232393856737 0 0.1715251685840043
EOD
$method1 << EOD
0.001 0.01653289794921875 NaN NaN 0.6191209081639815 0.20934238072552272
0.01 0.15087509155273438 NaN NaN 0.546643093830141 0.1715251685840043
EOD
$method2 << EOD
0.001 0.011632919311523436 NaN NaN 0.13924993295940502 0.20934238072552272
0.01 0.10361480712890624 NaN NaN 0.06217086077758549 0.1715251685840043
EOD
$method3 << EOD
0.001 0.007612320558558799 NaN NaN -0.25450048661363145 0.20934238072552272
0.01 0.07600902924623848 NaN NaN -0.22082009069510067 0.1715251685840043
EOD
$method4 << EOD
0.001 0.0046012439257811545 NaN NaN -0.5493850946955836 0.20934238072552272
0.01 0.040554882952487555 NaN NaN -0.5842658387542312 0.1715251685840043
EOD
set terminal pngcairo enhanced size 1400,1000 font ',11'
set output '.load_area.png.partial'
set multiplot layout 2,2 title 'surface_A_distributions_seed1: real contact area against load' noenhanced
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
set xrange [0:0.0103]
set yrange [0:0.1584188461303711]
plot $method0 using 1:3:4 with filledcurves fc rgb '#b0b0b0' fs transparent solid 0.5 notitle, \
     $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set title '(b) logarithmic axes'
set xrange [0.0007936507936507937:0.0126]
set yrange [0.003651780893477107:0.19010261535644532]
plot $method0 using 1:3:4 with filledcurves fc rgb '#b0b0b0' fs transparent solid 0.5 notitle, \
     $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle
set logscale x
unset logscale y
set format y '%g'
set yrange [*:*]
set title '(c) relative error against the reference'
set ylabel '{/:Italic A} / {/:Italic A}_{ref} - 1'
plot $method0 using 1:(-$6):6 with filledcurves fc rgb '#b0b0b0' fs transparent solid 0.5 notitle, \
     $method1 using 1:5 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:5 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:5 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:5 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
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
plot 2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title "bem (reference)" noenhanced, \
     2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' title "plateau" noenhanced, \
     2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' title "plateau_hertz (Hertz-consistent plateaus, this project)" noenhanced, \
     2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' title "persson" noenhanced, \
     2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' title "gw_mccool" noenhanced, \
     2 with filledcurves y1=3 fc rgb '#b0b0b0' fs transparent solid 0.5 title 'bem: its error estimate (area_fraction_error)' noenhanced
unset multiplot
set terminal svg enhanced size 1400,1000 dynamic font ',11'
set output '.load_area.svg.partial'
set multiplot layout 2,2 title 'surface_A_distributions_seed1: real contact area against load' noenhanced
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
set xrange [0:0.0103]
set yrange [0:0.1584188461303711]
plot $method0 using 1:3:4 with filledcurves fc rgb '#b0b0b0' fs transparent solid 0.5 notitle, \
     $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set title '(b) logarithmic axes'
set xrange [0.0007936507936507937:0.0126]
set yrange [0.003651780893477107:0.19010261535644532]
plot $method0 using 1:3:4 with filledcurves fc rgb '#b0b0b0' fs transparent solid 0.5 notitle, \
     $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle
set logscale x
unset logscale y
set format y '%g'
set yrange [*:*]
set title '(c) relative error against the reference'
set ylabel '{/:Italic A} / {/:Italic A}_{ref} - 1'
plot $method0 using 1:(-$6):6 with filledcurves fc rgb '#b0b0b0' fs transparent solid 0.5 notitle, \
     $method1 using 1:5 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:5 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:5 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:5 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
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
plot 2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' title "bem (reference)" noenhanced, \
     2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' title "plateau" noenhanced, \
     2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' title "plateau_hertz (Hertz-consistent plateaus, this project)" noenhanced, \
     2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' title "persson" noenhanced, \
     2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' title "gw_mccool" noenhanced, \
     2 with filledcurves y1=3 fc rgb '#b0b0b0' fs transparent solid 0.5 title 'bem: its error estimate (area_fraction_error)' noenhanced
unset multiplot
unset output
