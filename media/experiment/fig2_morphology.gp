set terminal pngcairo enhanced size 1500,1050 font "DejaVu Sans,11"
set output "fig2_morphology.png"
$p0 << EOD
0 39 5.015531433
1 39 5.713531696
EOD
$p1 << EOD
0 18.3 3.396239751
1 19.7 3.214723074
EOD
$p2 << EOD
0 7.3 1.801542549
1 3.6 0.8717797887
EOD
$p3 << EOD
0 21.7 5.529818161
1 20.9 5.72023698
EOD
$p4 << EOD
0 19.5 6.204389127
1 7 3.505551153
EOD
$p5 << EOD
0 3.9 1.580787427
1 1 0.4714045208
EOD
$p6 << EOD
0 29.4 5.916455395
1 25.1 6.028543218
EOD
$p7 << EOD
0 0.1775294158 0.04421818758
1 0.1729275961 0.03920263706
EOD
$p8 << EOD
0 0.01101261365 0.003365065596
1 0.01701380104 0.005324788783
EOD
$p9 << EOD
0 14.4 1.351542329
1 13.5 2.082999973
EOD
$p10 << EOD
0 21.2 2.542090129
1 19.9 3.643716052
EOD
$p11 << EOD
0 61.28774305 7.662041364
1 57.94545455 8.319561071
EOD
set multiplot layout 3,4 title "Figure 2: best-of-run robots (mean ± 1 s.e.; white feed-forward, red recurrent)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "spheres\nn = 10 / 10, p = 1" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "leaves\nn = 10 / 10, p = 0.7681" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "joints\nn = 10 / 10, p = 0.081" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "distance sensors\nn = 10 / 10, p = 0.921" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "touch sensors\nn = 10 / 10, p = 0.0964" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "proprioceptive sensors\nn = 10 / 10, p = 0.0957" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "time sensors\nn = 10 / 10, p = 0.6169" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "mean radius (m)\nn = 10 / 10, p = 0.9388" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "radius variance within a robot (m^2)\nn = 10 / 10, p = 0.3533" font ",10"
set yrange [0:*]
plot $p8 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p8 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p8 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "maximum depth from the root\nn = 10 / 10, p = 0.7212" font ",10"
set yrange [0:*]
plot $p9 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p9 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p9 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "spheres that touched the ground\nn = 10 / 10, p = 0.7732" font ",10"
set yrange [0:*]
plot $p10 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p10 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p10 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fraction of spheres that touched the ground\n(%)\nn = 10 / 10, p = 0.771" font ",10"
set yrange [0:*]
plot $p11 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p11 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p11 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
