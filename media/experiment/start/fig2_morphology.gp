set terminal pngcairo enhanced size 1500,1050 font "DejaVu Sans,11"
set output "fig2_morphology.png"
$p0 << EOD
0 50 0
1 42.2 4.046397575
EOD
$p1 << EOD
0 24.2 3.527038418
1 24.7 3.58716849
EOD
$p2 << EOD
0 3.6 2.357965225
1 2.9 0.5259911279
EOD
$p3 << EOD
0 31 9.481561053
1 9.7 2.394670007
EOD
$p4 << EOD
0 24.2 9.156418514
1 13.2 3.823320256
EOD
$p5 << EOD
0 62 18.96312211
1 23.4952381 4.702230324
EOD
$p6 << EOD
0 48.4 18.31283703
1 31.20952381 7.287578694
EOD
$p7 << EOD
0 100 0
1 70 15.27525232
EOD
$p8 << EOD
0 0.4 0.2449489743
1 1.8 0.6960204339
EOD
$p9 << EOD
0 41.8 5.06359556
1 24.4 4.681405297
EOD
$p10 << EOD
0 0.2719839082 0.07351941989
1 0.1034205238 0.01379131031
EOD
$p11 << EOD
0 0.01491051102 0.004127299347
1 0.01081691126 0.003882405728
EOD
$p12 << EOD
0 17.2 3.056141358
1 13 2.357022604
EOD
$p13 << EOD
0 30.2 4.973932046
1 13.4 2.300724524
EOD
$p14 << EOD
0 60.4 9.947864092
1 33.8 5.882145628
EOD
set multiplot layout 4,4 title "Figure 2: best-of-run robots (mean ± 1 s.e.; white recurrent (sparse start), red recurrent)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("recurrent (sparse start)" 0, "recurrent" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "spheres\nn = 5 / 10, p = 0.204" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "leaves\nn = 5 / 10, p = 0.9314" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "joints\nn = 5 / 10, p = 0.6993" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "distance sensors\nn = 5 / 10, p = 0.0121  *" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "touch sensors\nn = 5 / 10, p = 0.2084" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a robot's spheres with a distance\nsensor (%)\nn = 5 / 10, p = 0.0202  *" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a robot's spheres with a touch sensor\n(%)\nn = 5 / 10, p = 0.3103" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "best-of-run robots that hit max_spheres\n(share) (%)\nn = 5 / 10, p = 0.1961" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "proprioceptive sensors\nn = 5 / 10, p = 0.1918" font ",10"
set yrange [0:*]
plot $p8 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p8 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p8 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "time sensors\nn = 5 / 10, p = 0.0388  *" font ",10"
set yrange [0:*]
plot $p9 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p9 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p9 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "mean radius (m)\nn = 5 / 10, p = 0.0079  **" font ",10"
set yrange [0:*]
plot $p10 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p10 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p10 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "radius variance within a robot (m^2)\nn = 5 / 10, p = 0.5245" font ",10"
set yrange [0:*]
plot $p11 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p11 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p11 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "maximum depth from the root\nn = 5 / 10, p = 0.3106" font ",10"
set yrange [0:*]
plot $p12 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p12 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p12 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "spheres that touched the ground\nn = 5 / 10, p = 0.0036  **" font ",10"
set yrange [0:*]
plot $p13 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p13 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p13 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fraction of spheres that touched the ground\n(%)\nn = 5 / 10, p = 0.029  *" font ",10"
set yrange [0:*]
plot $p14 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p14 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p14 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
