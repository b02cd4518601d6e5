# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots; the data blocks below are the curves of curves.csv (load, A/A0, A/A0 -+ its error estimate,
# A/A_ref - 1, the reference's relative error estimate).
$method0 << EOD
1e-04 0.0007490953627533646 NaN NaN 0 NaN
0.00018846716378431193 0.0014713177215061935 NaN NaN 0 NaN
0.00035519871824902654 0.0028734772174272617 NaN NaN 0 NaN
0.0006694329500821695 0.005483026224740692 NaN NaN 0 NaN
0.0012616612944575134 0.01011798343712512 NaN NaN 0 NaN
0.0023778172582285123 0.018941784515621563 NaN NaN 0 NaN
0.004481404746557165 0.0379737201383237 NaN NaN 0 NaN
0.008445976423531822 0.07620547805191037 NaN NaN 0 NaN
0.01591789221932208 0.14787874857533123 NaN NaN 0 NaN
0.03 0.2798371678576795 NaN NaN 0 NaN
EOD
$method1 << EOD
1e-04 0.0010035502958579883 NaN NaN 0.33968296395448583 NaN
0.00018846716378431193 0.001876923076923077 NaN NaN 0.2756748929807382 NaN
0.00035519871824902654 0.0034816568047337276 NaN NaN 0.21165283079954023 NaN
0.0006694329500821695 0.007282840236686391 NaN NaN 0.32825194302819805 NaN
0.0012616612944575134 0.014397633136094675 NaN NaN 0.42297457053216503 NaN
0.0023778172582285123 0.02517869822485207 NaN NaN 0.3292674829072644 NaN
0.004481404746557165 0.044153846153846155 NaN NaN 0.16274744726117496 NaN
0.008445976423531822 0.09102011834319526 NaN NaN 0.19440387581052 NaN
0.01591789221932208 0.2050437869822485 NaN NaN 0.386566960821938 NaN
0.03 0.41619881656804736 NaN NaN 0.4872892680922183 NaN
EOD
$method2 << EOD
1e-04 0.0010627218934911242 NaN NaN 0.4186737047536886 NaN
0.00018846716378431193 0.002011834319526627 NaN NaN 0.36736905300583533 NaN
0.00035519871824902654 0.0037325443786982247 NaN NaN 0.29896431962669956 NaN
0.0006694329500821695 0.007971597633136094 NaN NaN 0.4538682301329122 NaN
0.0012616612944575134 0.015287573964497042 NaN NaN 0.5109309141981346 NaN
0.0023778172582285123 0.02661301775147929 NaN NaN 0.40498999603396135 NaN
0.004481404746557165 0.04681420118343195 NaN NaN 0.23280524038481776 NaN
0.008445976423531822 0.09829112426035502 NaN NaN 0.2898170416751422 NaN
0.01591789221932208 0.22077869822485208 NaN NaN 0.49297110201324656 NaN
0.03 0.44335147928994084 NaN NaN 0.5843194908098199 NaN
EOD
$method3 << EOD
1e-04 0.0007005917159763313 NaN NaN -0.06474962893743463 NaN
0.00018846716378431193 0.001323076923076923 NaN NaN -0.10075376396439784 NaN
0.00035519871824902654 0.0025491124260355025 NaN NaN -0.11288232578442914 NaN
0.0006694329500821695 0.0054023668639053245 NaN NaN -0.014710737743951374 NaN
0.0012616612944575134 0.009874556213017749 NaN NaN -0.024058867621208235 NaN
0.0023778172582285123 0.016969230769230764 NaN NaN -0.10413769329727118 NaN
0.004481404746557165 0.0318568047337278 NaN NaN -0.1610828589433514 NaN
0.008445976423531822 0.0710532544378698 NaN NaN -0.06760962263803294 NaN
0.01591789221932208 0.15401183431952659 NaN NaN 0.04147374658821312 NaN
0.03 0.29578579881656797 NaN NaN 0.05699253991521136 NaN
EOD
$method4 << EOD
1e-04 0.00043936888790102656 NaN NaN -0.41346735042373206 NaN
0.00018846716378431193 0.0008079828082116275 NaN NaN -0.4508440995433044 NaN
0.00035519871824902654 0.001482514864044384 NaN NaN -0.48406938636815133 NaN
0.0006694329500821695 0.002712937527293467 NaN NaN -0.5052116447935155 NaN
0.0012616612944575134 0.004948715570194824 NaN NaN -0.5108990244007623 NaN
0.0023778172582285123 0.008991941320747635 NaN NaN -0.5252854178901755 NaN
0.004481404746557165 0.016259849156118545 NaN NaN -0.5718131092531848 NaN
0.008445976423531822 0.029223064407383204 NaN NaN -0.6165227860984382 NaN
0.01591789221932208 0.05210768366740931 NaN NaN -0.6476323733503532 NaN
0.03 0.0919445592602515 NaN NaN -0.6714354995651866 NaN
EOD
$method5 << EOD
1e-04 0.00045066681027731444 NaN NaN -0.3983852621636187 NaN
0.00018846716378431193 0.0008341639354810729 NaN NaN -0.43304975989337224 NaN
0.00035519871824902654 0.0015409925766834015 NaN NaN -0.4637185333026188 NaN
0.0006694329500821695 0.002840152807239832 NaN NaN -0.48200999031804725 NaN
0.0012616612944575134 0.005219958081535409 NaN NaN -0.48409106281176273 NaN
0.0023778172582285123 0.009561003506428087 NaN NaN -0.49524272654759693 NaN
0.004481404746557165 0.017437529640012352 NaN NaN -0.540800069719424 NaN
0.008445976423531822 0.031630699042677346 NaN NaN -0.5849288023476364 NaN
0.01591789221932208 0.05697274304638155 NaN NaN -0.6147333974945093 NaN
0.03 0.10165700350057005 NaN NaN -0.6367280147994097 NaN
EOD
$method6 << EOD
1e-04 0.0006400560844142145 NaN NaN -0.14556127799051755 NaN
0.00018846716378431193 0.0012062955489243914 NaN NaN -0.1801257258768676 NaN
0.00035519871824902654 0.002273471007914197 NaN NaN -0.20880841019866303 NaN
0.0006694329500821695 0.004284746328074497 NaN NaN -0.21854352825439305 NaN
0.0012616612944575134 0.008075339879874454 NaN NaN -0.20188247687338123 NaN
0.0023778172582285123 0.015219364037542848 NaN NaN -0.19651899613834067 NaN
0.004481404746557165 0.028683503747566542 NaN NaN -0.24464857161522402 NaN
0.008445976423531822 0.054058985987005495 NaN NaN -0.2906154863278847 NaN
0.01591789221932208 0.10188343766026782 NaN NaN -0.31103394746157753 NaN
0.03 0.19201682532426434 NaN NaN -0.31382658424444565 NaN
EOD
$method7 << EOD
1e-04 0.0004074723410504476 NaN NaN -0.45604743893654887 NaN
0.00018846716378431193 0.0007679514791955582 NaN NaN -0.4780519068244462 NaN
0.00035519871824902654 0.0014473358018048704 NaN NaN -0.49631206643053616 NaN
0.0006694329500821695 0.002727748918496196 NaN NaN -0.50251032793023 NaN
0.0012616612944575134 0.00514088546571875 NaN NaN -0.4919061196665233 NaN
0.0023778172582285123 0.009688709952980767 NaN NaN -0.4885006771674364 NaN
0.004481404746557165 0.018258891688291336 NaN NaN -0.5191703203746909 NaN
0.008445976423531822 0.034404351144992684 NaN NaN -0.548531785056754 NaN
0.01591789221932208 0.06478964521243916 NaN NaN -0.5618731843714885 NaN
0.03 0.12176516765505274 NaN NaN -0.5648713550553782 NaN
EOD
set terminal pngcairo enhanced size 1400,1000 font ',11'
set output '.load_area.png.partial'
set multiplot layout 2,2 title 'measured_gap: real contact area against load' noenhanced
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
set yrange [0:0.46551905325443793]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
     $method5 using 1:2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' notitle, \
     $method6 using 1:2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' notitle, \
     $method7 using 1:2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' notitle
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set title '(b) logarithmic axes'
set xrange [7.936507936507937e-05:0.0378]
set yrange [0.00032339074686543463:0.5586228639053255]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
     $method5 using 1:2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' notitle, \
     $method6 using 1:2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' notitle, \
     $method7 using 1:2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' notitle
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
     2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' title "plateau_4" noenhanced, \
     2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' title "plateau_8" noenhanced, \
     2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' title "plateau_hertz (Hertz-consistent plateaus, this project)" noenhanced, \
     2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' title "gw_mccool" noenhanced, \
     2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' title "bgt" noenhanced, \
     2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' title "bgt_linear" noenhanced, \
     2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' title "persson" noenhanced
unset multiplot
set terminal svg enhanced size 1400,1000 dynamic font ',11'
set output '.load_area.svg.partial'
set multiplot layout 2,2 title 'measured_gap: real contact area against load' noenhanced
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
set yrange [0:0.46551905325443793]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
     $method5 using 1:2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' notitle, \
     $method6 using 1:2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' notitle, \
     $method7 using 1:2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' notitle
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set title '(b) logarithmic axes'
set xrange [7.936507936507937e-05:0.0378]
set yrange [0.00032339074686543463:0.5586228639053255]
plot $method0 using 1:2 with linespoints lw 3 pt 7 ps 0.8 lc rgb 'black' notitle, \
     $method1 using 1:2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' notitle, \
     $method2 using 1:2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' notitle, \
     $method3 using 1:2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' notitle, \
     $method4 using 1:2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' notitle, \
     $method5 using 1:2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' notitle, \
     $method6 using 1:2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' notitle, \
     $method7 using 1:2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' notitle
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
     2 with linespoints lw 1.5 pt 2 ps 0.9 lc rgb '#d55e00' title "plateau_4" noenhanced, \
     2 with linespoints lw 1.5 pt 3 ps 0.9 lc rgb '#009e73' title "plateau_8" noenhanced, \
     2 with linespoints lw 1.5 pt 4 ps 0.9 lc rgb '#cc79a7' title "plateau_hertz (Hertz-consistent plateaus, this project)" noenhanced, \
     2 with linespoints lw 1.5 pt 5 ps 0.9 lc rgb '#e69f00' title "gw_mccool" noenhanced, \
     2 with linespoints lw 1.5 pt 6 ps 0.9 lc rgb '#56b4e9' title "bgt" noenhanced, \
     2 with linespoints lw 1.5 pt 7 ps 0.9 lc rgb '#882255' title "bgt_linear" noenhanced, \
     2 with linespoints lw 1.5 pt 8 ps 0.9 lc rgb '#999933' title "persson" noenhanced
unset multiplot
unset output
