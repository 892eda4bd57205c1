set terminal pngcairo enhanced size 1500,1050 font "DejaVu Sans,11"
set output "fig2_morphology.png"
$p0 << EOD
0 46.83333333 1.927468314
1 46.83333333 1.813159643
EOD
$p1 << EOD
0 22.16666667 1.678863418
1 25.7 1.529893693
EOD
$p2 << EOD
0 8.966666667 1.774327351
1 4.133333333 0.5728198717
EOD
$p3 << EOD
0 27.33333333 3.241020605
1 19.13333333 2.641287275
EOD
$p4 << EOD
0 12.13333333 3.005257207
1 18.73333333 2.814140539
EOD
$p5 << EOD
0 60.92972973 6.60887255
1 42.53333333 5.660253301
EOD
$p6 << EOD
0 24.26666667 6.010514414
1 37.98636364 5.529646323
EOD
$p7 << EOD
0 90 5.570860145
1 90 5.570860145
EOD
$p8 << EOD
0 3.033333333 1.263532117
1 1.966666667 0.3996646104
EOD
$p9 << EOD
0 33.96666667 3.038633742
1 28.33333333 2.69667029
EOD
$p10 << EOD
0 0.1392925334 0.01616815698
1 0.1223384605 0.01530204366
EOD
$p11 << EOD
0 0.01251130747 0.002196945534
1 0.01102680907 0.002283132817
EOD
$p12 << EOD
0 18.9 1.475742556
1 13.4 0.8835664407
EOD
$p13 << EOD
0 25.66666667 2.508987676
1 15.06666667 1.432731764
EOD
$p14 << EOD
0 57.13333333 5.191224543
1 33.47056277 2.998226948
EOD
set multiplot layout 4,4 title "Figure 2: best-of-run robots (mean ± 1 s.e.; white feed-forward, red recurrent)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "spheres\nn = 30 / 30, p = 1" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "leaves\nn = 30 / 30, p = 0.1252" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "joints\nn = 30 / 30, p = 0.012  *" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "distance sensors\nn = 30 / 30, p = 0.0547" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "touch sensors\nn = 30 / 30, p = 0.1144" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a robot's spheres with a distance\nsensor (%)\nn = 30 / 30, p = 0.0388  *" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a robot's spheres with a touch sensor\n(%)\nn = 30 / 30, p = 0.0984" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "best-of-run robots that hit max\\_spheres\n(share) (%)\nn = 30 / 30, p = 1" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "proprioceptive sensors\nn = 30 / 30, p = 0.4242" font ",10"
set yrange [0:*]
plot $p8 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p8 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p8 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "time sensors\nn = 30 / 30, p = 0.1709" font ",10"
set yrange [0:*]
plot $p9 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p9 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p9 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "mean radius (m)\nn = 30 / 30, p = 0.4494" font ",10"
set yrange [0:*]
plot $p10 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p10 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p10 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "radius variance within a robot (m^2)\nn = 30 / 30, p = 0.6412" font ",10"
set yrange [0:*]
plot $p11 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p11 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p11 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "maximum depth from the root\nn = 30 / 30, p = 0.0022  **" font ",10"
set yrange [0:*]
plot $p12 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p12 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p12 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "spheres that touched the ground\nn = 30 / 30, p = 0.0005  ***" font ",10"
set yrange [0:*]
plot $p13 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p13 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p13 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fraction of spheres that touched the ground\n(%)\nn = 30 / 30, p = 0.0002  ***" font ",10"
set yrange [0:*]
plot $p14 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p14 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p14 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
