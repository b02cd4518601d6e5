# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots; the data blocks below are the curves of curves.csv (load, A/A0, A/A0 -+ its error estimate,
# A/A_ref - 1, the reference's relative error estimate).
$method0 << EOD
0.001 1 NaN NaN 0 NaN
0.00197435048583482 1 NaN NaN 0 NaN
0.0038980598409161897 1 NaN NaN 0 NaN
0.007696136340726078 1 NaN NaN 0 NaN
0.015194870523363548 1 NaN NaN 0 NaN
0.03 1 NaN NaN 0 NaN
EOD
$method1 << EOD
0.001 0.014609362289423397 NaN NaN -0.9853906377105766 NaN
0.00197435048583482 0.028809516482161724 NaN NaN -0.9711904835178383 NaN
0.0038980598409161897 0.05555362926432977 NaN NaN -0.9444463707356703 NaN
0.007696136340726078 0.10663270809643073 NaN NaN -0.8933672919035692 NaN
0.015194870523363548 0.20226464848627712 NaN NaN -0.7977353515137229 NaN
0.03 0.3740500091589221 NaN NaN -0.6259499908410779 NaN
EOD
$method2 << EOD
0.001 0.017646789550781247 NaN NaN -0.9823532104492188 NaN
0.00197435048583482 0.03507995605468749 NaN NaN -0.9649200439453125 NaN
0.0038980598409161897 0.06626129150390624 NaN NaN -0.9337387084960938 NaN
0.007696136340726078 0.12409210205078124 NaN NaN -0.8759078979492188 NaN
0.015194870523363548 0.22714233398437494 NaN NaN -0.772857666015625 NaN
0.03 0.3662643432617187 NaN NaN -0.6337356567382812 NaN
EOD
$method3 << EOD
0.001 0.010765542451598884 NaN NaN -0.9892344575484011 NaN
0.00197435048583482 0.021253085055136317 NaN NaN -0.9787469149448637 NaN
0.0038980598409161897 0.04194666095771873 NaN NaN -0.9580533390422813 NaN
0.007696136340726078 0.08270692358606595 NaN NaN -0.9172930764139341 NaN
0.015194870523363548 0.1624471186397443 NaN NaN -0.8375528813602557 NaN
0.03 0.31436847210152663 NaN NaN -0.6856315278984734 NaN
EOD
$method4 << EOD
0.001 0.007427999781331621 NaN NaN -0.9925720002186684 NaN
0.00197435048583482 0.014129272224853284 NaN NaN -0.9858707277751467 NaN
0.0038980598409161897 0.026739913776940856 NaN NaN -0.9732600862230592 NaN
0.007696136340726078 0.050278483825250755 NaN NaN -0.9497215161747492 NaN
0.015194870523363548 0.09373818872096537 NaN NaN -0.9062618112790346 NaN
0.03 0.17277832742231455 NaN NaN -0.8272216725776854 NaN
EOD
$method5 << EOD
0.001 0.03565665972920507 NaN NaN -0.9643433402707949 NaN
0.00197435048583482 0.05845449527373553 NaN NaN -0.9415455047262644 NaN
0.0038980598409161897 0.09573961880498316 NaN NaN -0.9042603811950168 NaN
0.007696136340726078 0.15616431426223004 NaN NaN -0.84383568573777 NaN
0.015194870523363548 0.2527659635724336 NaN NaN -0.7472340364275665 NaN
0.03 0.4042351240243504 NaN NaN -0.5957648759756495 NaN
EOD
$method6 << EOD
0.001 0.03682685625931985 NaN NaN -0.9631731437406802 NaN
0.00197435048583482 0.05948507847906776 NaN NaN -0.9405149215209322 NaN
0.0038980598409161897 0.09632301371354511 NaN NaN -0.9036769862864549 NaN
0.007696136340726078 0.15577696596588456 NaN NaN -0.8442230340341155 NaN
0.015194870523363548 0.2505985998368487 NaN NaN -0.7494014001631513 NaN
0.03 0.39917148202435165 NaN NaN -0.6008285179756483 NaN
EOD
$method7 << EOD
0.001 0.06984834461618009 NaN NaN -0.9301516553838199 NaN
0.00197435048583482 0.09549469810588368 NaN NaN -0.9045053018941163 NaN
0.0038980598409161897 0.1354858845718819 NaN NaN -0.8645141154281181 NaN
0.007696136340726078 0.19745583056721275 NaN NaN -0.8025441694327873 NaN
0.015194870523363548 0.2928850474613503 NaN NaN -0.7071149525386498 NaN
0.03 0.43849478834232497 NaN NaN -0.5615052116576751 NaN
EOD
$method8 << EOD
0.001 0.7216339111328125 NaN NaN -0.2783660888671875 NaN
0.00197435048583482 0.76226806640625 NaN NaN -0.23773193359375 NaN
0.0038980598409161897 0.77520751953125 NaN NaN -0.22479248046875 NaN
0.007696136340726078 0.8218994140625 NaN NaN -0.1781005859375 NaN
0.015194870523363548 0.8766937255859375 NaN NaN -0.1233062744140625 NaN
0.03 0.9585113525390625 NaN NaN -0.0414886474609375 NaN
EOD
$method9 << EOD
0.001 0.32452392578125 NaN NaN -0.67547607421875 NaN
0.00197435048583482 0.3314056396484375 NaN NaN -0.6685943603515625 NaN
0.0038980598409161897 0.34912109375 NaN NaN -0.65087890625 NaN
0.007696136340726078 0.38854217529296875 NaN NaN -0.6114578247070312 NaN
0.015194870523363548 0.43834686279296875 NaN NaN -0.5616531372070312 NaN
0.03 0.493133544921875 NaN NaN -0.506866455078125 NaN
EOD
set terminal pngcairo enhanced size 1400,1000 font ',11'
set output '.load_area.png.partial'
set multiplot layout 2,2 title 'adhesion_A_soft_tabor_5: real contact area against load' noenhanced
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
set xrange [0:0.0309]
set yrange [0:1.05]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
     $method5 using 1:2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' notitle, \
     $method6 using 1:2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' notitle, \
     $method7 using 1:2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' notitle, \
     $method8 using 1:2 with linespoints lw 1.5 pt 9 ps 0.9 lc rgb '#44aa99' notitle, \
     $method9 using 1:2 with linespoints lw 1.5 pt 10 ps 0.9 lc rgb '#aa4499' notitle
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set title '(b) logarithmic axes'
set xrange [0.0007936507936507937:0.0378]
set yrange [0.005895237921691763:1.26]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
     $method5 using 1:2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' notitle, \
     $method6 using 1:2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' notitle, \
     $method7 using 1:2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' notitle, \
     $method8 using 1:2 with linespoints lw 1.5 pt 9 ps 0.9 lc rgb '#44aa99' notitle, \
     $method9 using 1:2 with linespoints lw 1.5 pt 10 ps 0.9 lc rgb '#aa4499' notitle
set logscale x
unset logscale y
set format y '%g'
set yrange [*:*]
set title '(c) relative error against the reference'
set ylabel '{/:Italic A} / {/:Italic A}_{ref} - 1'
plot $method1 using 1:5 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:5 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:5 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:5 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
     $method5 using 1:5 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' notitle, \
     $method6 using 1:5 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' notitle, \
     $method7 using 1:5 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' notitle, \
     $method8 using 1:5 with linespoints lw 1.5 pt 9 ps 0.9 lc rgb '#44aa99' notitle, \
     $method9 using 1:5 with linespoints lw 1.5 pt 10 ps 0.9 lc rgb '#aa4499' notitle, \
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
     2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' title "bem_non_adhesive (non-adhesive: ignores adhesion)" noenhanced, \
     2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' title "plateau_hertz (Hertz-consistent plateaus, this project; non-adhesive: ignores adhesion)" noenhanced, \
     2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' title "persson (non-adhesive: ignores adhesion)" noenhanced, \
     2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' title "gw_mccool (non-adhesive: ignores adhesion)" noenhanced, \
     2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' title "fuller_tabor (GW summits each a JKR sphere)" noenhanced, \
     2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' title "maugis_gw (GW summits each a Maugis-Dugdale sphere)" noenhanced, \
     2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' title "maugis_gw_retract (GW summits each a Maugis-Dugdale sphere)" noenhanced, \
     2 with linespoints lw 1.5 pt 9 ps 0.9 lc rgb '#44aa99' title "plateau_kendall (plateaus as Kendall punches, this project)" noenhanced, \
     2 with linespoints lw 1.5 pt 10 ps 0.9 lc rgb '#aa4499' title "plateau_hertz_jkr (Hertz-consistent plateaus as JKR contacts, this project)" noenhanced
unset multiplot
set terminal svg enhanced size 1400,1000 dynamic font ',11'
set output '.load_area.svg.partial'
set multiplot layout 2,2 title 'adhesion_A_soft_tabor_5: real contact area against load' noenhanced
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
set xrange [0:0.0309]
set yrange [0:1.05]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
     $method5 using 1:2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' notitle, \
     $method6 using 1:2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' notitle, \
     $method7 using 1:2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' notitle, \
     $method8 using 1:2 with linespoints lw 1.5 pt 9 ps 0.9 lc rgb '#44aa99' notitle, \
     $method9 using 1:2 with linespoints lw 1.5 pt 10 ps 0.9 lc rgb '#aa4499' notitle
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set title '(b) logarithmic axes'
set xrange [0.0007936507936507937:0.0378]
set yrange [0.005895237921691763:1.26]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
     $method5 using 1:2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' notitle, \
     $method6 using 1:2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' notitle, \
     $method7 using 1:2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' notitle, \
     $method8 using 1:2 with linespoints lw 1.5 pt 9 ps 0.9 lc rgb '#44aa99' notitle, \
     $method9 using 1:2 with linespoints lw 1.5 pt 10 ps 0.9 lc rgb '#aa4499' notitle
set logscale x
unset logscale y
set format y '%g'
set yrange [*:*]
set title '(c) relative error against the reference'
set ylabel '{/:Italic A} / {/:Italic A}_{ref} - 1'
plot $method1 using 1:5 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:5 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:5 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:5 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
     $method5 using 1:5 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' notitle, \
     $method6 using 1:5 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' notitle, \
     $method7 using 1:5 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' notitle, \
     $method8 using 1:5 with linespoints lw 1.5 pt 9 ps 0.9 lc rgb '#44aa99' notitle, \
     $method9 using 1:5 with linespoints lw 1.5 pt 10 ps 0.9 lc rgb '#aa4499' notitle, \
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
     2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' title "bem_non_adhesive (non-adhesive: ignores adhesion)" noenhanced, \
     2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' title "plateau_hertz (Hertz-consistent plateaus, this project; non-adhesive: ignores adhesion)" noenhanced, \
     2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' title "persson (non-adhesive: ignores adhesion)" noenhanced, \
     2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' title "gw_mccool (non-adhesive: ignores adhesion)" noenhanced, \
     2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' title "fuller_tabor (GW summits each a JKR sphere)" noenhanced, \
     2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' title "maugis_gw (GW summits each a Maugis-Dugdale sphere)" noenhanced, \
     2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' title "maugis_gw_retract (GW summits each a Maugis-Dugdale sphere)" noenhanced, \
     2 with linespoints lw 1.5 pt 9 ps 0.9 lc rgb '#44aa99' title "plateau_kendall (plateaus as Kendall punches, this project)" noenhanced, \
     2 with linespoints lw 1.5 pt 10 ps 0.9 lc rgb '#aa4499' title "plateau_hertz_jkr (Hertz-consistent plateaus as JKR contacts, this project)" noenhanced
unset multiplot
unset output
