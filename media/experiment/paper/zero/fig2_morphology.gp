set terminal pngcairo enhanced size 1500,1050 font "DejaVu Sans,11"
set output "fig2_morphology.png"
$p0 << EOD
0 46.8 1.933610761
1 45.5 1.946260783
EOD
$p1 << EOD
0 22.3 1.732813804
1 26.06666667 1.721355609
EOD
$p2 << EOD
0 9.5 1.819277361
1 3.666666667 0.4582157634
EOD
$p3 << EOD
0 29.76666667 3.23475499
1 18.46666667 2.425787386
EOD
$p4 << EOD
0 13.23333333 2.87545432
1 16.1 2.363199662
EOD
$p5 << EOD
0 65.93333333 6.475760876
1 40.75163399 5.132815656
EOD
$p6 << EOD
0 26.46666667 5.750908641
1 35.85727867 5.001742005
EOD
$p7 << EOD
0 90 5.570860145
1 83.33333333 6.920456654
EOD
$p8 << EOD
0 2.666666667 0.9829972151
1 1.333333333 0.3785432857
EOD
$p9 << EOD
0 31.5 3.264138125
1 29 2.730416161
EOD
$p10 << EOD
0 0.1462843156 0.01820246785
1 0.115650046 0.01164377372
EOD
$p11 << EOD
0 0.01291368702 0.002485272711
1 0.01104945095 0.00220405382
EOD
$p12 << EOD
0 19.36666667 1.475067373
1 11.83333333 0.7413614896
EOD
$p13 << EOD
0 27.36666667 2.428037064
1 13.1 1.405530946
EOD
$p14 << EOD
0 60.6 4.903810388
1 29.56054664 2.871717575
EOD
set multiplot layout 4,4 title "Figure 2: best-of-run robots (mean ± 1 s.e.; white feed-forward, red recurrent (zero-weight start))"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent (zero-weight start)" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "spheres\nn = 30 / 30, p = 0.6374" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "leaves\nn = 30 / 30, p = 0.1285" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "joints\nn = 30 / 30, p = 0.0029  **" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "distance sensors\nn = 30 / 30, p = 0.007  **" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "touch sensors\nn = 30 / 30, p = 0.4443" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a robot's spheres with a distance\nsensor (%)\nn = 30 / 30, p = 0.0035  **" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a robot's spheres with a touch sensor\n(%)\nn = 30 / 30, p = 0.2229" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "best-of-run robots that hit max\\_spheres\n(share) (%)\nn = 30 / 30, p = 0.456" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "proprioceptive sensors\nn = 30 / 30, p = 0.2107" font ",10"
set yrange [0:*]
plot $p8 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p8 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p8 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "time sensors\nn = 30 / 30, p = 0.5592" font ",10"
set yrange [0:*]
plot $p9 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p9 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p9 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "mean radius (m)\nn = 30 / 30, p = 0.1616" font ",10"
set yrange [0:*]
plot $p10 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p10 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p10 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "radius variance within a robot (m^2)\nn = 30 / 30, p = 0.5768" font ",10"
set yrange [0:*]
plot $p11 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p11 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p11 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "maximum depth from the root\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p12 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p12 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p12 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "spheres that touched the ground\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p13 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p13 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p13 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fraction of spheres that touched the ground\n(%)\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p14 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p14 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p14 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
