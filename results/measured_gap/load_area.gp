# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder redraws
# the plots; the data blocks below are the curves of curves.csv (load, A/A0, A/A0 -+ its error estimate,
# A/A_ref - 1, the reference's relative error estimate).
$method0 << EOD
1e-04 0.0007370002776790447 NaN NaN 0 NaN
0.00018846716378431193 0.0014657641078649802 NaN NaN 0 NaN
0.00035519871824902654 0.00285567934134414 NaN NaN 0 NaN
0.0006694329500821695 0.005419028105710544 NaN NaN 0 NaN
0.0012616612944575134 0.010015333198966685 NaN NaN 0 NaN
0.0023778172582285123 0.019000063407813864 NaN NaN 0 NaN
0.004481404746557165 0.03724684158889989 NaN NaN 0 NaN
0.008445976423531822 0.07562852363420002 NaN NaN 0 NaN
0.01591789221932208 0.14606633129804086 NaN NaN 0 NaN
0.03 0.26048075924250486 NaN NaN 0 NaN
EOD
$method1 << EOD
1e-04 0.0010035502958579883 NaN NaN 0.3616688164872348 NaN
0.00018846716378431193 0.001876923076923077 NaN NaN 0.28050828018772234 NaN
0.00035519871824902654 0.0034816568047337276 NaN NaN 0.2192043953698759 NaN
0.0006694329500821695 0.007282840236686391 NaN NaN 0.34393845069963214 NaN
0.0012616612944575134 0.014397633136094675 NaN NaN 0.437559075676097 NaN
0.0023778172582285123 0.02517869822485207 NaN NaN 0.32519022091774774 NaN
0.004481404746557165 0.044153846153846155 NaN NaN 0.18543866460356884 NaN
0.008445976423531822 0.09102011834319526 NaN NaN 0.20351573677996537 NaN
0.01591789221932208 0.2050437869822485 NaN NaN 0.4037717327470023 NaN
0.03 0.41619881656804736 NaN NaN 0.5978102097766484 NaN
EOD
$method2 << EOD
1e-04 0.0010627218934911242 NaN NaN 0.4419558929310574 NaN
0.00018846716378431193 0.002011834319526627 NaN NaN 0.37254985896540216 NaN
0.00035519871824902654 0.0037325443786982247 NaN NaN 0.3070600486052306 NaN
0.0006694329500821695 0.007971597633136094 NaN NaN 0.4710382521795127 NaN
0.0012616612944575134 0.015287573964497042 NaN NaN 0.5264169110294115 NaN
0.0023778172582285123 0.02661301775147929 NaN NaN 0.4006804703890916 NaN
0.004481404746557165 0.04681420118343195 NaN NaN 0.2568636476651829 NaN
0.008445976423531822 0.09829112426035502 NaN NaN 0.29965679001972134 NaN
0.01591789221932208 0.22077869822485208 NaN NaN 0.5114961556360613 NaN
0.03 0.44335147928994084 NaN NaN 0.7020507794097193 NaN
EOD
$method3 << EOD
1e-04 0.0007005917159763313 NaN NaN -0.04940101490513815 NaN
0.00018846716378431193 0.001323076923076923 NaN NaN -0.09734662216275325 NaN
0.00035519871824902654 0.0025491124260355025 NaN NaN -0.1073534100521032 NaN
0.0006694329500821695 0.0054023668639053245 NaN NaN -0.003074581175849911 NaN
0.0012616612944575134 0.009874556213017749 NaN NaN -0.01405614602652061 NaN
0.0023778172582285123 0.016969230769230764 NaN NaN -0.10688557164224566 NaN
0.004481404746557165 0.0318568047337278 NaN NaN -0.14471124598060947 NaN
0.008445976423531822 0.0710532544378698 NaN NaN -0.06049660864014572 NaN
0.01591789221932208 0.15401183431952659 NaN NaN 0.05439653992043736 NaN
0.03 0.29578579881656797 NaN NaN 0.135537993964439 NaN
EOD
$method4 << EOD
1e-04 0.00043936888790102656 NaN NaN -0.4038416250198935 NaN
0.00018846716378431193 0.0008079828082116275 NaN NaN -0.44876341024032274 NaN
0.00035519871824902654 0.001482514864044384 NaN NaN -0.48085387508998856 NaN
0.0006694329500821695 0.002712937527293467 NaN NaN -0.49936824936659996 NaN
0.0012616612944575134 0.004948715570194824 NaN NaN -0.5058860776888183 NaN
0.0023778172582285123 0.008991941320747635 NaN NaN -0.5267415098704535 NaN
0.004481404746557165 0.016259849156118545 NaN NaN -0.5634569680945989 NaN
0.008445976423531822 0.029223064407383204 NaN NaN -0.6135973174786632 NaN
0.01591789221932208 0.05210768366740931 NaN NaN -0.6432601325415215 NaN
0.03 0.0919445592602515 NaN NaN -0.647019766344231 NaN
EOD
$method5 << EOD
1e-04 0.00045066681027731444 NaN NaN -0.38851202105845783 NaN
0.00018846716378431193 0.0008341639354810729 NaN NaN -0.4309016498595336 NaN
0.00035519871824902654 0.0015409925766834015 NaN NaN -0.4603761863689949 NaN
0.0006694329500821695 0.002840152807239832 NaN NaN -0.4758925859330949 NaN
0.0012616612944575134 0.005219958081535409 NaN NaN -0.47880335303532695 NaN
0.0023778172582285123 0.009561003506428087 NaN NaN -0.4967909684713957 NaN
0.004481404746557165 0.017437529640012352 NaN NaN -0.5318387037356479 NaN
0.008445976423531822 0.031630699042677346 NaN NaN -0.5817623097382056 NaN
0.01591789221932208 0.05697274304638155 NaN NaN -0.6099529402834689 NaN
0.03 0.10165700350057005 NaN NaN -0.609733157273515 NaN
EOD
$method6 << EOD
1e-04 0.0006400560844142145 NaN NaN -0.13153888295690486 NaN
0.00018846716378431193 0.0012062955489243914 NaN NaN -0.17701931541940163 NaN
0.00035519871824902654 0.002273471007914197 NaN NaN -0.203877348902872 NaN
0.0006694329500821695 0.004284746328074497 NaN NaN -0.20931461426464026 NaN
0.0012616612944575134 0.008075339879874454 NaN NaN -0.19370232428137157 NaN
0.0023778172582285123 0.015219364037542848 NaN NaN -0.19898351332428632 NaN
0.004481404746557165 0.028683503747566542 NaN NaN -0.22990775797444662 NaN
0.008445976423531822 0.054058985987005495 NaN NaN -0.28520373809651556 NaN
0.01591789221932208 0.10188343766026782 NaN NaN -0.30248513291964674 NaN
0.03 0.19201682532426434 NaN NaN -0.2628368180334629 NaN
EOD
$method7 << EOD
1e-04 0.0004074723410504476 NaN NaN -0.44712050539023374 NaN
0.00018846716378431193 0.0007679514791955582 NaN NaN -0.47607430481146795 NaN
0.00035519871824902654 0.0014473358018048704 NaN NaN -0.4931728570324623 NaN
0.0006694329500821695 0.002727748918496196 NaN NaN -0.4966350302516962 NaN
0.0012616612944575134 0.00514088546571875 NaN NaN -0.48669850881754473 NaN
0.0023778172582285123 0.009688709952980767 NaN NaN -0.49006959897848335 NaN
0.004481404746557165 0.018258891688291336 NaN NaN -0.5097868460950858 NaN
0.008445976423531822 0.034404351144992684 NaN NaN -0.545087627104826 NaN
0.01591789221932208 0.06478964521243916 NaN NaN -0.5564368281405028 NaN
0.03 0.12176516765505274 NaN NaN -0.5325368061381814 NaN
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
