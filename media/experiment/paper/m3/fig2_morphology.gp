set terminal pngcairo enhanced size 1500,1050 font "DejaVu Sans,11"
set output "fig2_morphology.png"
$p0 << EOD
0 47.96666667 1.243357832
1 49.4 0.6
EOD
$p1 << EOD
0 25.3 1.378112986
1 27.56666667 1.120019841
EOD
$p2 << EOD
0 4.5 1.210822842
1 4.433333333 0.6152904806
EOD
$p3 << EOD
0 16.3 2.616986949
1 20.43333333 2.763341029
EOD
$p4 << EOD
0 13.5 2.616371973
1 26.6 2.475906893
EOD
$p5 << EOD
0 33.29064872 5.218328606
1 41.01666667 5.497882734
EOD
$p6 << EOD
0 29.33926846 5.549709049
1 54.25 5.081901061
EOD
$p7 << EOD
0 90 5.570860145
1 96.66666667 3.333333333
EOD
$p8 << EOD
0 2.333333333 0.9496924285
1 1.366666667 0.2647199055
EOD
$p9 << EOD
0 25.4 3.12336394
1 28.23333333 2.17809541
EOD
$p10 << EOD
0 0.2099602955 0.0170821199
1 0.1162126539 0.01189128672
EOD
$p11 << EOD
0 0.01880595443 0.001605685107
1 0.01018782885 0.002240913133
EOD
$p12 << EOD
0 14.96666667 0.9425855043
1 14.23333333 0.7469221648
EOD
$p13 << EOD
0 20.86666667 1.814838794
1 14.9 1.246005111
EOD
$p14 << EOD
0 44.09468599 3.664731203
1 30.025 2.446330527
EOD
set multiplot layout 4,4 title "Figure 2: best-of-run robots (mean ± 1 s.e.; white feed-forward, red recurrent)"
set style fill solid 1.0 border rgb "black"
set boxwidth 0.6
set xrange [-0.6:1.6]
set xtics ("feed-forward" 0, "recurrent" 1) scale 0
set grid ytics
set key off
set offsets 0, 0, graph 0.1, 0
set title "spheres\nn = 30 / 30, p = 0.3035" font ",10"
set yrange [0:*]
plot $p0 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p0 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p0 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "leaves\nn = 30 / 30, p = 0.2069" font ",10"
set yrange [0:*]
plot $p1 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p1 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p1 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "joints\nn = 30 / 30, p = 0.961" font ",10"
set yrange [0:*]
plot $p2 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p2 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p2 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "distance sensors\nn = 30 / 30, p = 0.282" font ",10"
set yrange [0:*]
plot $p3 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p3 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p3 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "touch sensors\nn = 30 / 30, p = 0.0006  ***" font ",10"
set yrange [0:*]
plot $p4 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p4 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p4 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a robot's spheres with a distance\nsensor (%)\nn = 30 / 30, p = 0.3123" font ",10"
set yrange [0:*]
plot $p5 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p5 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p5 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "share of a robot's spheres with a touch sensor\n(%)\nn = 30 / 30, p = 0.0016  **" font ",10"
set yrange [0:*]
plot $p6 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p6 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p6 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "best-of-run robots that hit max\\_spheres\n(share) (%)\nn = 30 / 30, p = 0.3087" font ",10"
set yrange [0:*]
plot $p7 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p7 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p7 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "proprioceptive sensors\nn = 30 / 30, p = 0.3309" font ",10"
set yrange [0:*]
plot $p8 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p8 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p8 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "time sensors\nn = 30 / 30, p = 0.4598" font ",10"
set yrange [0:*]
plot $p9 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p9 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p9 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "mean radius (m)\nn = 30 / 30, p < 0.0001  ***" font ",10"
set yrange [0:*]
plot $p10 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p10 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p10 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "radius variance within a robot (m^2)\nn = 30 / 30, p = 0.0028  **" font ",10"
set yrange [0:*]
plot $p11 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p11 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p11 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "maximum depth from the root\nn = 30 / 30, p = 0.5444" font ",10"
set yrange [0:*]
plot $p12 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p12 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p12 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "spheres that touched the ground\nn = 30 / 30, p = 0.0088  **" font ",10"
set yrange [0:*]
plot $p13 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p13 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p13 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
set title "fraction of spheres that touched the ground\n(%)\nn = 30 / 30, p = 0.0023  **" font ",10"
set yrange [0:*]
plot $p14 every ::0::0 using 1:2 with boxes lc rgb "#ffffff", \
     $p14 every ::1::1 using 1:2 with boxes lc rgb "#d62728", \
     $p14 using 1:2:3 with yerrorbars lc rgb "black" pt 7 ps 0.5
unset multiplot
unset output
