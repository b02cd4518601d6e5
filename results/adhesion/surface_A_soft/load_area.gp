# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots; the data blocks below are the curves of curves.csv (load, A/A0, A/A0 -+ its error estimate,
# A/A_ref - 1, the reference's relative error estimate).
$method0 << EOD
0.001 0.33049889638813856 NaN NaN 0 NaN
0.00197435048583482 0.3422678374569449 NaN NaN 0 NaN
0.0038980598409161897 0.3649698484228016 NaN NaN 0 NaN
0.007696136340726078 0.4042378457639363 NaN NaN 0 NaN
0.015194870523363548 0.47765344547602606 NaN NaN 0 NaN
0.03 0.6051069530902765 NaN NaN 0 NaN
EOD
$method1 << EOD
0.001 0.014609362289423397 0.01146150170241401 0.017757222876432784 -0.9557960330606788 NaN
0.00197435048583482 0.028809516482161724 0.022851614493090297 0.03476741847123315 -0.9158275673922012 NaN
0.0038980598409161897 0.05555362926432977 0.04491232493848828 0.06619493359017126 -0.8477857020123665 NaN
0.007696136340726078 0.10663270809643073 0.08790421722184968 0.12536119897101178 -0.736212951820693 NaN
0.015194870523363548 0.20226464848627712 0.172045186850987 0.23248411012156725 -0.5765451910752961 NaN
0.03 0.3740500091589221 0.33079891654066307 0.41730110177718116 -0.381844800743651 NaN
EOD
$method2 << EOD
0.001 0.017646789550781247 NaN NaN -0.9466056021861664 NaN
0.00197435048583482 0.03507995605468749 NaN NaN -0.8975072962878076 NaN
0.0038980598409161897 0.06626129150390624 NaN NaN -0.8184472175160469 NaN
0.007696136340726078 0.12409210205078124 NaN NaN -0.693022057802951 NaN
0.015194870523363548 0.22714233398437494 NaN NaN -0.5244620631637934 NaN
0.03 0.3662643432617187 NaN NaN -0.39471139541330746 NaN
EOD
$method3 << EOD
0.001 0.010765542451598884 NaN NaN -0.9674263891067406 NaN
0.00197435048583482 0.021253085055136317 NaN NaN -0.9379051060916297 NaN
0.0038980598409161897 0.04194666095771873 NaN NaN -0.8850681470291613 NaN
0.007696136340726078 0.08270692358606595 NaN NaN -0.7954003454828311 NaN
0.015194870523363548 0.1624471186397443 NaN NaN -0.6599059000237073 NaN
0.03 0.31436847210152663 NaN NaN -0.4804745334753645 NaN
EOD
$method4 << EOD
0.001 0.007427999781331621 NaN NaN -0.9775248877908259 NaN
0.00197435048583482 0.014129272224853284 NaN NaN -0.9587186680179067 NaN
0.0038980598409161897 0.026739913776940856 NaN NaN -0.9267339099586006 NaN
0.007696136340726078 0.050278483825250755 NaN NaN -0.8756215323425902 NaN
0.015194870523363548 0.09373818872096537 NaN NaN -0.8037527215415634 NaN
0.03 0.17277832742231455 NaN NaN -0.7144664649118029 NaN
EOD
$method5 << EOD
0.001 0.03565665972920507 NaN NaN -0.892112620892598 NaN
0.00197435048583482 0.05845449527373553 NaN NaN -0.8292141741740816 NaN
0.0038980598409161897 0.09573961880498316 NaN NaN -0.737678004857889 NaN
0.007696136340726078 0.15616431426223004 NaN NaN -0.6136821034974898 NaN
0.015194870523363548 0.2527659635724336 NaN NaN -0.4708172505266265 NaN
0.03 0.4042351240243504 NaN NaN -0.3319608674798319 NaN
EOD
$method6 << EOD
0.001 0.0907928878016857 NaN NaN -0.7252853525566441 NaN
0.00197435048583482 0.10241861875847218 NaN NaN -0.7007647007693039 NaN
0.0038980598409161897 0.1229662974619567 NaN NaN -0.6630782022313646 NaN
0.007696136340726078 0.15817509523849957 NaN NaN -0.6087078513403976 NaN
0.015194870523363548 0.21718637405781369 NaN NaN -0.5453055429310946 NaN
0.03 0.31476019282538076 NaN NaN -0.47982717564572197 NaN
EOD
$method7 << EOD
0.001 0.0936708023913739 NaN NaN -0.7165775637526888 NaN
0.00197435048583482 0.10544656464855716 NaN NaN -0.6919179861244729 NaN
0.0038980598409161897 0.1262161848710071 NaN NaN -0.6541736655330739 NaN
0.007696136340726078 0.1617021176626202 NaN NaN -0.5999827345284 NaN
0.015194870523363548 0.22096724967126705 NaN NaN -0.537390022485753 NaN
0.03 0.3185965939058135 NaN NaN -0.47348713763948147 NaN
EOD
$method8 << EOD
0.001 0.7216339111328125 NaN NaN 1.1834684442798387 NaN
0.00197435048583482 0.76226806640625 NaN NaN 1.2271098332519732 NaN
0.0038980598409161897 0.77520751953125 NaN NaN 1.1240316779078308 NaN
0.007696136340726078 0.8218994140625 NaN NaN 1.0332074858286933 NaN
0.015194870523363548 0.8766937255859375 NaN NaN 0.835417987432773 NaN
0.03 0.9585113525390625 NaN NaN 0.5840362561427406 NaN
EOD
$method9 << EOD
0.001 0.32452392578125 NaN NaN -0.018078640117065725 NaN
0.00197435048583482 0.3314056396484375 NaN NaN -0.03173595827529019 NaN
0.0038980598409161897 0.34912109375 NaN NaN -0.043424832876718944 NaN
0.007696136340726078 0.38854217529296875 NaN NaN -0.0388278104968266 NaN
0.015194870523363548 0.43834686279296875 NaN NaN -0.08229100628361352 NaN
0.03 0.493133544921875 NaN NaN -0.1850473004756501 NaN
EOD
set terminal pngcairo enhanced size 1400,1000 font ',11'
set output '.load_area.png.partial'
set multiplot layout 2,2 title 'adhesion_A_soft: real contact area against load' noenhanced
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
set yrange [0:1.0064369201660157]
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
set yrange [0.005895237921691763:1.2077243041992187]
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
set multiplot layout 2,2 title 'adhesion_A_soft: real contact area against load' noenhanced
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
set yrange [0:1.0064369201660157]
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
set yrange [0.005895237921691763:1.2077243041992187]
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
