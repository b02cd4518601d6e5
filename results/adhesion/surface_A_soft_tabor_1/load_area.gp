# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots; the data blocks below are the curves of curves.csv (load, A/A0, A/A0 -+ its error estimate,
# A/A_ref - 1, the reference's relative error estimate).
$method0 << EOD
0.001 0.7310640750671167 NaN NaN 0 NaN
0.00197435048583482 0.8097605186913627 NaN NaN 0 NaN
0.0038980598409161897 0.8379347862489833 NaN NaN 0 NaN
0.007696136340726078 0.9015927883109673 NaN NaN 0 NaN
0.015194870523363548 0.9430786646540797 NaN NaN 0 NaN
0.03 0.9713796676474132 NaN NaN 0 NaN
EOD
$method1 << EOD
0.001 0.014609362289423397 NaN NaN -0.9800163039223584 NaN
0.00197435048583482 0.028809516482161724 NaN NaN -0.9644221769064264 NaN
0.0038980598409161897 0.05555362926432977 NaN NaN -0.9337017269410479 NaN
0.007696136340726078 0.10663270809643073 NaN NaN -0.8817285259166778 NaN
0.015194870523363548 0.20226464848627712 NaN NaN -0.7855272777690634 NaN
0.03 0.3740500091589221 NaN NaN -0.6149291346968022 NaN
EOD
$method2 << EOD
0.001 0.017646789550781247 NaN NaN -0.9758615008552278 NaN
0.00197435048583482 0.03507995605468749 NaN NaN -0.9566786040502697 NaN
0.0038980598409161897 0.06626129150390624 NaN NaN -0.9209230925946814 NaN
0.007696136340726078 0.12409210205078124 NaN NaN -0.862363470893269 NaN
0.015194870523363548 0.22714233398437494 NaN NaN -0.7591480514855137 NaN
0.03 0.3662643432617187 NaN NaN -0.6229441942626046 NaN
EOD
$method3 << EOD
0.001 0.010765542451598884 NaN NaN -0.9852741465231888 NaN
0.00197435048583482 0.021253085055136317 NaN NaN -0.9737538635626704 NaN
0.0038980598409161897 0.04194666095771873 NaN NaN -0.9499404229946187 NaN
0.007696136340726078 0.08270692358606595 NaN NaN -0.9082657662546214 NaN
0.015194870523363548 0.1624471186397443 NaN NaN -0.8277480715785998 NaN
0.03 0.31436847210152663 NaN NaN -0.6763691040981984 NaN
EOD
$method4 << EOD
0.001 0.007427999781331621 NaN NaN -0.9898394682016762 NaN
0.00197435048583482 0.014129272224853284 NaN NaN -0.98255129523024 NaN
0.0038980598409161897 0.026739913776940856 NaN NaN -0.968088311625488 NaN
0.007696136340726078 0.050278483825250755 NaN NaN -0.9442337111863529 NaN
0.015194870523363548 0.09373818872096537 NaN NaN -0.9006040617456356 NaN
0.03 0.17277832742231455 NaN NaN -0.8221310027614982 NaN
EOD
$method5 << EOD
0.001 0.03565665972920507 NaN NaN -0.9512263549184364 NaN
0.00197435048583482 0.05845449527373553 NaN NaN -0.9278126138229082 NaN
0.0038980598409161897 0.09573961880498316 NaN NaN -0.8857433533299629 NaN
0.007696136340726078 0.15616431426223004 NaN NaN -0.8267906350994818 NaN
0.015194870523363548 0.2527659635724336 NaN NaN -0.731977858214884 NaN
0.03 0.4042351240243504 NaN NaN -0.583854657980058 NaN
EOD
$method6 << EOD
0.001 0.03933204235157595 NaN NaN -0.9461989123894988 NaN
0.00197435048583482 0.059136785170078365 NaN NaN -0.9269700315030818 NaN
0.0038980598409161897 0.09088119071964791 NaN NaN -0.8915414514219206 NaN
0.007696136340726078 0.14170776900438303 NaN NaN -0.8428250859572018 NaN
0.015194870523363548 0.2227135402587599 NaN NaN -0.7638441536152756 NaN
0.03 0.35057872453678557 NaN NaN -0.63909196762801 NaN
EOD
$method7 << EOD
0.001 0.06280889991796776 NaN NaN -0.9140856430235592 NaN
0.00197435048583482 0.0837221232767419 NaN NaN -0.8966087857530477 NaN
0.0038980598409161897 0.11678174662362777 NaN NaN -0.8606314613737407 NaN
0.007696136340726078 0.16866595816541402 NaN NaN -0.8129244595208102 NaN
0.015194870523363548 0.24971170205402152 NaN NaN -0.7352164655897337 NaN
0.03 0.3755676282026705 NaN NaN -0.613366801147631 NaN
EOD
$method8 << EOD
0.001 0.7216339111328125 NaN NaN -0.01289923039022045 NaN
0.00197435048583482 0.76226806640625 NaN NaN -0.05864999736201548 NaN
0.0038980598409161897 0.77520751953125 NaN NaN -0.07485936584460473 NaN
0.007696136340726078 0.8218994140625 NaN NaN -0.08839176098309742 NaN
0.015194870523363548 0.8766937255859375 NaN NaN -0.0703917303573951 NaN
0.03 0.9585113525390625 NaN NaN -0.013247461869895338 NaN
EOD
$method9 << EOD
0.001 0.32452392578125 NaN NaN -0.5560937312485824 NaN
0.00197435048583482 0.3314056396484375 NaN NaN -0.5907362337398032 NaN
0.0038980598409161897 0.34912109375 NaN NaN -0.5833552927038138 NaN
0.007696136340726078 0.38854217529296875 NaN NaN -0.5690491535309873 NaN
0.015194870523363548 0.43834686279296875 NaN NaN -0.5351958651786975 NaN
0.03 0.493133544921875 NaN NaN -0.49233697044926183 NaN
EOD
set terminal pngcairo enhanced size 1400,1000 font ',11'
set output '.load_area.png.partial'
set multiplot layout 2,2 title 'adhesion_A_soft_tabor_1: real contact area against load' noenhanced
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
set yrange [0:1.019948651029784]
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
set yrange [0.005895237921691763:1.2239383812357407]
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
set multiplot layout 2,2 title 'adhesion_A_soft_tabor_1: real contact area against load' noenhanced
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
set yrange [0:1.019948651029784]
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
set yrange [0.005895237921691763:1.2239383812357407]
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
