set terminal pngcairo enhanced size 1500,1050 font "DejaVu Sans,11"
set output "fig2_morphology.png"
$p0 << EOD
0 50 0
1 50 0
EOD
$p1 << EOD
0 26.9 1.741327718
1 24.2 3.527038418
EOD
$p2 << EOD
0 5.5 1.661659144
1 3.6 2.357965225
EOD
$p3 << EOD
0 36.3 5.389392874
1 31 9.481561053
EOD
$p4 << EOD
0 18.8 5.915704147
1 24.2 9.156418514
EOD
$p5 << EOD
0 72.6 10.77878575
1 62 18.96312211
EOD
$p6 << EOD
0 37.6 11.83140829
1 48.4 18.31283703
EOD
$p7 << EOD
0 100 0
1 100 0
EOD
$p8 << EOD
0 1 0.557773351
1 0.4 0.2449489743
EOD
$p9 << EOD
0 30.2 6.306610289
1 41.8 5.06359556
EOD
$p10 << EOD
0 0.1808465881 0.03311660536
1 0.2719839082 0.07351941989
EOD
$p11 << EOD
0 0.01818026041 0.004309735133
1 0.01491051102 0.004127299347
EOD
$p12 << EOD
0 15.6 1.886796226
1 17.2 3.056141358
EOD
$p13 << EOD
0 23.7 3.627211969
1 30.2 4.973932046
EOD
$p14 << EOD
0 47.4 7.254423938
1 60.4 9.947864092
EOD
set multiplot layout 4,4 title "Figure 2: best-of-run robots (mean ± 1 s.e.; white feed-forward, red recurrent (sparse start))"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent (sparse start)" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "spheres\nn = 10 / 5" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "leaves\nn = 10 / 5, p = 0.4504" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "joints\nn = 10 / 5, p = 0.5211" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "distance sensors\nn = 10 / 5, p = 0.6083" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "touch sensors\nn = 10 / 5, p = 0.6175" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a robot's spheres with a distance\nsensor (%)\nn = 10 / 5, p = 0.6083" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a robot's spheres with a touch sensor\n(%)\nn = 10 / 5, p = 0.6175" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "best-of-run robots that hit max_spheres\n(share) (%)\nn = 10 / 5" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "proprioceptive sensors\nn = 10 / 5, p = 0.4778" font ",10"
set yrange [0:*]
plot $p8 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p8 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p8 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "time sensors\nn = 10 / 5, p = 0.2539" font ",10"
set yrange [0:*]
plot $p9 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p9 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p9 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "mean radius (m)\nn = 10 / 5, p = 0.2099" font ",10"
set yrange [0:*]
plot $p10 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p10 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p10 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "radius variance within a robot (m^2)\nn = 10 / 5, p = 0.6393" font ",10"
set yrange [0:*]
plot $p11 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p11 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p11 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "maximum depth from the root\nn = 10 / 5, p = 0.6478" font ",10"
set yrange [0:*]
plot $p12 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p12 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p12 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "spheres that touched the ground\nn = 10 / 5, p = 0.3154" font ",10"
set yrange [0:*]
plot $p13 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p13 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p13 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fraction of spheres that touched the ground\n(%)\nn = 10 / 5, p = 0.3154" font ",10"
set yrange [0:*]
plot $p14 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p14 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p14 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
