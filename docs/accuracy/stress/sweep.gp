# Error against ns per world-step, one curve per knob: written by
# ./build/tools/manyworlds sweep --scenes spring-0.1,spring-0.25,spring-0.5,spring-1.0,spin-unstable,flywheel,singular-hinge-90,singular-hinge-180,singular-fixed-90,singular-fixed-180,singular-slider-90,singular-rackpinion,singular-cone,singular-swingtwist,dt-1/15,dt-1e-4,mass-range,mass-range-hanging,far-1e4,chain16-r1000,chain64 --worlds 256 --passes 2 --out docs/accuracy/stress
# Run: gnuplot sweep.gp (in this directory).
set terminal pngcairo noenhanced size 1500,900 font ',10'
set logscale xy
set grid
set format y '%.0e'
set key below horizontal
set xlabel 'ns per world-step (256 worlds, 1 thread(s), AVX3)'
$spring_0_1_substeps << EOD
1 14.87 0.2865 0.9102 5.534 0.4506 0 NaN NaN 1
2 26.69 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
4 49.89 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
8 100.2 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
EOD
$spring_0_1_velocity_iterations << EOD
1 13.87 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
2 14.51 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
4 14.53 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
8 14.33 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
10 14.87 0.2865 0.9102 5.534 0.4506 0 NaN NaN 1
EOD
$spring_0_1_position_iterations << EOD
0 14.39 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
1 14.37 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
2 14.87 0.2865 0.9102 5.534 0.4506 0 NaN NaN 1
EOD
$spring_0_1_default << EOD
0 14.87 0.2865 0.9102 5.534 0.4506 0 NaN NaN 1
EOD
set output 'spring-0.1.png'
set multiplot layout 2,3 title 'spring-0.1: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $spring_0_1_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_1_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_1_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_1_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_1_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_1_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_1_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $spring_0_1_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_1_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_1_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_1_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_1_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_1_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_1_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $spring_0_1_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_1_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_1_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_1_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_1_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_1_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_1_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $spring_0_1_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_1_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_1_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_1_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_1_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_1_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_1_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$spring_0_25_substeps << EOD
1 14.72 0.1082 0.6185 5.832 0.4001 0 NaN NaN 1
2 27.07 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
4 51.99 0.2179 0.7383 11 0.278 0 NaN NaN 0
8 105.6 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
EOD
$spring_0_25_velocity_iterations << EOD
1 14.13 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
2 15.1 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
4 15.5 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
8 15.54 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
10 14.72 0.1082 0.6185 5.832 0.4001 0 NaN NaN 1
EOD
$spring_0_25_position_iterations << EOD
0 14.38 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
1 15.48 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
2 14.72 0.1082 0.6185 5.832 0.4001 0 NaN NaN 1
EOD
$spring_0_25_default << EOD
0 14.72 0.1082 0.6185 5.832 0.4001 0 NaN NaN 1
EOD
set output 'spring-0.25.png'
set multiplot layout 2,3 title 'spring-0.25: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $spring_0_25_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_25_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_25_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_25_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_25_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_25_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_25_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $spring_0_25_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_25_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_25_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_25_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_25_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_25_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_25_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $spring_0_25_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_25_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_25_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_25_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_25_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_25_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_25_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $spring_0_25_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_25_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_25_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_25_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_25_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_25_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_25_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$spring_0_5_substeps << EOD
1 16.43 0.0457 0.2884 6.438 0.216 0 NaN NaN 1
2 26.94 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
4 55.16 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
8 109 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
EOD
$spring_0_5_velocity_iterations << EOD
1 14.16 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
2 15.09 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
4 15.93 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
8 15.95 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
10 16.43 0.0457 0.2884 6.438 0.216 0 NaN NaN 1
EOD
$spring_0_5_position_iterations << EOD
0 16.4 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
1 16.2 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
2 16.43 0.0457 0.2884 6.438 0.216 0 NaN NaN 1
EOD
$spring_0_5_default << EOD
0 16.43 0.0457 0.2884 6.438 0.216 0 NaN NaN 1
EOD
set output 'spring-0.5.png'
set multiplot layout 2,3 title 'spring-0.5: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $spring_0_5_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_5_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_5_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_5_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_5_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_5_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_5_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $spring_0_5_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_5_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_5_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_5_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_5_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_5_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_5_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $spring_0_5_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_5_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_5_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_5_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_5_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_5_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_5_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $spring_0_5_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_5_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_5_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_5_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_5_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_5_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_5_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$spring_1_0_substeps << EOD
1 18.93 0.0156 0.092 7.166 0.1529 0 NaN NaN 1
2 35.45 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
4 62.84 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
8 111.5 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
EOD
$spring_1_0_velocity_iterations << EOD
1 14.91 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
2 16.04 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
4 17.35 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
8 18.59 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
10 18.93 0.0156 0.092 7.166 0.1529 0 NaN NaN 1
EOD
$spring_1_0_position_iterations << EOD
0 17.84 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
1 19.35 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
2 18.93 0.0156 0.092 7.166 0.1529 0 NaN NaN 1
EOD
$spring_1_0_default << EOD
0 18.93 0.0156 0.092 7.166 0.1529 0 NaN NaN 1
EOD
set output 'spring-1.0.png'
set multiplot layout 2,3 title 'spring-1.0: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $spring_1_0_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_1_0_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_1_0_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_1_0_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_1_0_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_1_0_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_1_0_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $spring_1_0_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_1_0_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_1_0_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_1_0_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_1_0_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_1_0_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_1_0_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $spring_1_0_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_1_0_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_1_0_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_1_0_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_1_0_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_1_0_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_1_0_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $spring_1_0_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_1_0_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_1_0_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_1_0_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_1_0_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_1_0_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_1_0_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$spin_unstable_substeps << EOD
1 9.233 0 0 0 0 2.727e-06 4.597e-08 NaN 1
2 15.53 0 0 0 0 8.518e-07 9.265e-08 NaN 0
4 28.15 0 0 0 0 6.444e-07 1.714e-07 NaN 0
8 53.14 0 0 0 0 1.885e-07 5.714e-07 NaN 0
EOD
$spin_unstable_velocity_iterations << EOD
1 9.244 0 0 0 0 2.727e-06 4.597e-08 NaN 0
2 8.807 0 0 0 0 2.727e-06 4.597e-08 NaN 0
4 9.136 0 0 0 0 2.727e-06 4.597e-08 NaN 0
8 8.914 0 0 0 0 2.727e-06 4.597e-08 NaN 0
10 9.233 0 0 0 0 2.727e-06 4.597e-08 NaN 1
EOD
$spin_unstable_position_iterations << EOD
0 8.87 0 0 0 0 2.727e-06 4.597e-08 NaN 0
1 8.527 0 0 0 0 2.727e-06 4.597e-08 NaN 0
2 9.233 0 0 0 0 2.727e-06 4.597e-08 NaN 1
EOD
$spin_unstable_default << EOD
0 9.233 0 0 0 0 2.727e-06 4.597e-08 NaN 1
EOD
set output 'spin-unstable.png'
set multiplot layout 1,3 title 'spin-unstable: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'trajectory error RMS (rad)'
plot $spin_unstable_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spin_unstable_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spin_unstable_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spin_unstable_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spin_unstable_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spin_unstable_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spin_unstable_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $spin_unstable_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spin_unstable_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spin_unstable_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spin_unstable_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spin_unstable_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spin_unstable_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spin_unstable_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$flywheel_substeps << EOD
1 42.74 0 0 0 0 1.151e-06 0 NaN 1
2 84.52 0 0 0 0 1.563e-06 0 NaN 0
4 164.8 0 0 0 0 1.719e-06 0 NaN 0
8 341.5 0 0 0 0 1.39e-06 0 NaN 0
EOD
$flywheel_velocity_iterations << EOD
1 33 0 0 3.145e-10 0 1.151e-06 0 NaN 0
2 34.92 0 0 4.687e-18 0 1.151e-06 0 NaN 0
4 39.49 0 0 1.041e-33 0 1.151e-06 0 NaN 0
8 43.37 0 0 0 0 1.151e-06 0 NaN 0
10 42.74 0 0 0 0 1.151e-06 0 NaN 1
EOD
$flywheel_position_iterations << EOD
0 26.64 0 0 0 0 1.151e-06 0 NaN 0
1 42.11 0 0 0 0 1.151e-06 0 NaN 0
2 42.74 0 0 0 0 1.151e-06 0 NaN 1
EOD
$flywheel_default << EOD
0 42.74 0 0 0 0 1.151e-06 0 NaN 1
EOD
set output 'flywheel.png'
set multiplot layout 1,3 title 'flywheel: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $flywheel_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $flywheel_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $flywheel_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $flywheel_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $flywheel_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $flywheel_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $flywheel_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $flywheel_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $flywheel_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $flywheel_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $flywheel_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $flywheel_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $flywheel_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $flywheel_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_hinge_90_substeps << EOD
1 72.02 0.07896 0.4775 0 0 0.07896 0 NaN 1
2 141.1 0.0417 0.2955 0 0 0.04169 0 NaN 0
4 284.9 0.01558 0.119 0 0 0.01558 0 NaN 0
8 570.7 0.00257 0.0199 0 0 0.002569 0 NaN 0
EOD
$singular_hinge_90_velocity_iterations << EOD
1 72.68 0.07896 0.4775 0 0 0.07896 0 NaN 0
2 73.55 0.07896 0.4775 0 0 0.07896 0 NaN 0
4 74.02 0.07896 0.4775 0 0 0.07896 0 NaN 0
8 73.74 0.07896 0.4775 0 0 0.07896 0 NaN 0
10 72.02 0.07896 0.4775 0 0 0.07896 0 NaN 1
EOD
$singular_hinge_90_position_iterations << EOD
0 22.07 1.571 1.571 0 0 1.571 0 NaN 0
1 46.43 0.1285 0.6204 0 0 0.1285 0 NaN 0
2 72.02 0.07896 0.4775 0 0 0.07896 0 NaN 1
EOD
$singular_hinge_90_default << EOD
0 72.02 0.07896 0.4775 0 0 0.07896 0 NaN 1
EOD
set output 'singular-hinge-90.png'
set multiplot layout 1,3 title 'singular-hinge-90: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_hinge_90_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_90_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_90_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_90_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_90_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_90_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_90_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_hinge_90_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_90_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_90_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_90_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_90_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_90_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_90_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_hinge_90_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_90_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_90_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_90_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_90_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_90_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_90_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_hinge_180_substeps << EOD
1 72.9 0.1804 1.241 0 0 0.1804 0 NaN 1
2 145.3 0.07055 0.5027 0 0 0.07055 0 NaN 0
4 291 0.02562 0.1957 0 0 0.02562 0 NaN 0
8 581.6 0.004203 0.03255 0 0 0.004203 0 NaN 0
EOD
$singular_hinge_180_velocity_iterations << EOD
1 72.95 0.1804 1.241 0 0 0.1804 0 NaN 0
2 73.36 0.1804 1.241 0 0 0.1804 0 NaN 0
4 73 0.1804 1.241 0 0 0.1804 0 NaN 0
8 71.15 0.1804 1.241 0 0 0.1804 0 NaN 0
10 72.9 0.1804 1.241 0 0 0.1804 0 NaN 1
EOD
$singular_hinge_180_position_iterations << EOD
0 22.27 3.142 3.142 0 0 3.142 0 NaN 0
1 46.79 0.3522 2.191 0 0 0.3522 0 NaN 0
2 72.9 0.1804 1.241 0 0 0.1804 0 NaN 1
EOD
$singular_hinge_180_default << EOD
0 72.9 0.1804 1.241 0 0 0.1804 0 NaN 1
EOD
set output 'singular-hinge-180.png'
set multiplot layout 1,3 title 'singular-hinge-180: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_hinge_180_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_180_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_180_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_180_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_180_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_180_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_180_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_hinge_180_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_180_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_180_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_180_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_180_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_180_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_180_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_hinge_180_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_180_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_180_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_180_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_180_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_180_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_180_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_fixed_90_substeps << EOD
1 38.64 0.1777 1.048 0 0 0.1777 0 NaN 1
2 76.76 0.09687 0.6832 0 0 0.09687 0 NaN 0
4 153.3 0.03706 0.283 0 0 0.03706 0 NaN 0
8 305 0.006146 0.04759 0 0 0.006145 0 NaN 0
EOD
$singular_fixed_90_velocity_iterations << EOD
1 38.83 0.1777 1.048 0 0 0.1777 0 NaN 0
2 39.09 0.1777 1.048 0 0 0.1777 0 NaN 0
4 39.78 0.1777 1.048 0 0 0.1777 0 NaN 0
8 38.37 0.1777 1.048 0 0 0.1777 0 NaN 0
10 38.64 0.1777 1.048 0 0 0.1777 0 NaN 1
EOD
$singular_fixed_90_position_iterations << EOD
0 14.94 1.571 1.571 0 0 1.571 0 NaN 0
1 26.83 0.2824 1.288 0 0 0.2824 0 NaN 0
2 38.64 0.1777 1.048 0 0 0.1777 0 NaN 1
EOD
$singular_fixed_90_default << EOD
0 38.64 0.1777 1.048 0 0 0.1777 0 NaN 1
EOD
set output 'singular-fixed-90.png'
set multiplot layout 1,3 title 'singular-fixed-90: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_fixed_90_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_90_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_90_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_90_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_90_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_90_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_90_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_fixed_90_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_90_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_90_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_90_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_90_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_90_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_90_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_fixed_90_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_90_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_90_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_90_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_90_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_90_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_90_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_fixed_180_substeps << EOD
1 38.54 0.415 2.35 0 0 0.415 0 NaN 1
2 76.24 0.2358 1.646 0 0 0.2358 0 NaN 0
4 155 0.09435 0.7202 0 0 0.09435 0 NaN 0
8 301.9 0.01584 0.1226 0 0 0.01584 0 NaN 0
EOD
$singular_fixed_180_velocity_iterations << EOD
1 38.48 0.415 2.35 0 0 0.415 0 NaN 0
2 38.46 0.415 2.35 0 0 0.415 0 NaN 0
4 38.72 0.415 2.35 0 0 0.415 0 NaN 0
8 38.78 0.415 2.35 0 0 0.415 0 NaN 0
10 38.54 0.415 2.35 0 0 0.415 0 NaN 1
EOD
$singular_fixed_180_position_iterations << EOD
0 15.26 3.142 3.142 0 0 3.142 0 NaN 0
1 26.59 0.6451 2.742 0 0 0.6451 0 NaN 0
2 38.54 0.415 2.35 0 0 0.415 0 NaN 1
EOD
$singular_fixed_180_default << EOD
0 38.54 0.415 2.35 0 0 0.415 0 NaN 1
EOD
set output 'singular-fixed-180.png'
set multiplot layout 1,3 title 'singular-fixed-180: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_fixed_180_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_180_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_180_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_180_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_180_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_180_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_180_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_fixed_180_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_180_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_180_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_180_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_180_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_180_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_180_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_fixed_180_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_180_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_180_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_180_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_180_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_180_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_180_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_slider_90_substeps << EOD
1 56.9 0.1777 1.048 0 0 0.1777 0 NaN 1
2 114.1 0.09687 0.6832 0 0 0.09687 0 NaN 0
4 236 0.03706 0.283 0 0 0.03706 0 NaN 0
8 466.7 0.006146 0.04759 0 0 0.006145 0 NaN 0
EOD
$singular_slider_90_velocity_iterations << EOD
1 58.3 0.1777 1.048 0 0 0.1777 0 NaN 0
2 58.34 0.1777 1.048 0 0 0.1777 0 NaN 0
4 59.22 0.1777 1.048 0 0 0.1777 0 NaN 0
8 59.09 0.1777 1.048 0 0 0.1777 0 NaN 0
10 56.9 0.1777 1.048 0 0 0.1777 0 NaN 1
EOD
$singular_slider_90_position_iterations << EOD
0 19.35 1.571 1.571 0 0 1.571 0 NaN 0
1 39.26 0.2824 1.288 0 0 0.2824 0 NaN 0
2 56.9 0.1777 1.048 0 0 0.1777 0 NaN 1
EOD
$singular_slider_90_default << EOD
0 56.9 0.1777 1.048 0 0 0.1777 0 NaN 1
EOD
set output 'singular-slider-90.png'
set multiplot layout 1,3 title 'singular-slider-90: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_slider_90_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_slider_90_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_slider_90_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_slider_90_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_slider_90_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_slider_90_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_slider_90_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_slider_90_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_slider_90_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_slider_90_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_slider_90_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_slider_90_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_slider_90_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_slider_90_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_slider_90_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_slider_90_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_slider_90_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_slider_90_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_slider_90_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_slider_90_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_slider_90_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_rackpinion_substeps << EOD
1 163 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 1
2 333.7 2.365e-07 1.008e-06 2.819e-08 0.000787 0.00787 NaN 4.096e-07 0
4 663.8 3.791e-07 1.483e-06 3.07e-08 0.0003151 0.003152 NaN 6.566e-07 0
8 1336 5.745e-07 1.811e-06 8.009e-09 0.0001102 0.001103 NaN 9.95e-07 0
EOD
$singular_rackpinion_velocity_iterations << EOD
1 115.2 9.967e-08 3.934e-07 4.623e-08 0.001406 0.01406 NaN 1.726e-07 0
2 121.1 6.963e-08 2.934e-07 4.733e-08 0.000979 0.00979 NaN 1.206e-07 0
4 134.9 2.363e-07 8.783e-07 3.464e-08 0.0008912 0.008912 NaN 4.093e-07 0
8 155.9 2.22e-07 7.791e-07 2.862e-08 0.0008904 0.008905 NaN 3.845e-07 0
10 163 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 1
EOD
$singular_rackpinion_position_iterations << EOD
0 85.06 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 0
1 128.3 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 0
2 163 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 1
EOD
$singular_rackpinion_default << EOD
0 163 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 1
EOD
set output 'singular-rackpinion.png'
set multiplot layout 2,3 title 'singular-rackpinion: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_rackpinion_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_rackpinion_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $singular_rackpinion_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $singular_rackpinion_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_rackpinion_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'coupling error RMS (rad)'
plot $singular_rackpinion_substeps using 2:9 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:9 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:9 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:9 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_cone_substeps << EOD
1 42.61 0.345 1.904 0 0 0.345 0 NaN 1
2 85.33 0.1975 1.308 0 0 0.1975 0 NaN 0
4 168.4 0.08914 0.6489 0 0 0.08914 0 NaN 0
8 335 0.0283 0.216 0 0 0.0283 0 NaN 0
EOD
$singular_cone_velocity_iterations << EOD
1 42.78 0.345 1.904 0 0 0.345 0 NaN 0
2 42.83 0.345 1.904 0 0 0.345 0 NaN 0
4 42.88 0.345 1.904 0 0 0.345 0 NaN 0
8 42.6 0.345 1.904 0 0 0.345 0 NaN 0
10 42.61 0.345 1.904 0 0 0.345 0 NaN 1
EOD
$singular_cone_position_iterations << EOD
0 17.01 2.642 2.642 0 0 2.642 0 NaN 0
1 29.98 0.5366 2.266 0 0 0.5366 0 NaN 0
2 42.61 0.345 1.904 0 0 0.345 0 NaN 1
EOD
$singular_cone_default << EOD
0 42.61 0.345 1.904 0 0 0.345 0 NaN 1
EOD
set output 'singular-cone.png'
set multiplot layout 1,3 title 'singular-cone: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_cone_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_cone_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_cone_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_cone_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_cone_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_cone_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_cone_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_cone_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_cone_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_cone_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_cone_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_cone_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_cone_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_cone_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_cone_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_cone_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_cone_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_cone_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_cone_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_cone_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_cone_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_swingtwist_substeps << EOD
1 54.68 0.3282 1.893 0 0 0.3282 0 NaN 1
2 106.9 0.1833 1.286 0 0 0.1833 0 NaN 0
4 211.6 0.07181 0.5482 0 0 0.0718 0 NaN 0
8 415.4 0.01198 0.09275 0 0 0.01198 0 NaN 0
EOD
$singular_swingtwist_velocity_iterations << EOD
1 54.09 0.3282 1.893 0 0 0.3282 0 NaN 0
2 54.58 0.3282 1.893 0 0 0.3282 0 NaN 0
4 54.99 0.3282 1.893 0 0 0.3282 0 NaN 0
8 53.76 0.3282 1.893 0 0 0.3282 0 NaN 0
10 54.68 0.3282 1.893 0 0 0.3282 0 NaN 1
EOD
$singular_swingtwist_position_iterations << EOD
0 25.86 2.642 2.642 0 0 2.642 0 NaN 0
1 39.03 0.5146 2.254 0 0 0.5146 0 NaN 0
2 54.68 0.3282 1.893 0 0 0.3282 0 NaN 1
EOD
$singular_swingtwist_default << EOD
0 54.68 0.3282 1.893 0 0 0.3282 0 NaN 1
EOD
set output 'singular-swingtwist.png'
set multiplot layout 1,3 title 'singular-swingtwist: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_swingtwist_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_swingtwist_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_swingtwist_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_swingtwist_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_swingtwist_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_swingtwist_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_swingtwist_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_swingtwist_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_swingtwist_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_swingtwist_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_swingtwist_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_swingtwist_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_swingtwist_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_swingtwist_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_swingtwist_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_swingtwist_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_swingtwist_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_swingtwist_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_swingtwist_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_swingtwist_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_swingtwist_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$dt_1_15_substeps << EOD
1 678.6 0.07143 0.2983 0.4198 0.6856 0.4034 136.9 NaN 1
2 1369 0.01701 0.0394 0.09734 0.2071 0.07676 57.27 NaN 0
4 2728 0.006135 0.01548 0.04657 0.07069 0.02554 24.65 NaN 0
8 5495 0.002338 0.006265 0.0234 0.02274 0.009772 11.09 NaN 0
EOD
$dt_1_15_velocity_iterations << EOD
1 479.9 0.1235 0.4805 0.5309 1.152 0.5927 163.6 NaN 0
2 509.9 0.09798 0.3396 0.3387 1.008 0.5285 171 NaN 0
4 557.2 0.08218 0.2822 0.3838 0.8337 0.456 155.1 NaN 0
8 642.5 0.07618 0.303 0.4244 0.7265 0.4367 142.8 NaN 0
10 678.6 0.07143 0.2983 0.4198 0.6856 0.4034 136.9 NaN 1
EOD
$dt_1_15_position_iterations << EOD
0 400.7 0.1054 0.5405 0.6645 0.8272 0.5476 130.3 NaN 0
1 549.5 0.07735 0.3392 0.478 0.7165 0.4531 138.7 NaN 0
2 678.6 0.07143 0.2983 0.4198 0.6856 0.4034 136.9 NaN 1
EOD
$dt_1_15_default << EOD
0 678.6 0.07143 0.2983 0.4198 0.6856 0.4034 136.9 NaN 1
EOD
set output 'dt-1_15.png'
set multiplot layout 2,3 title 'dt-1/15: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $dt_1_15_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $dt_1_15_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $dt_1_15_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $dt_1_15_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $dt_1_15_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $dt_1_15_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$dt_1e_4_substeps << EOD
1 711.5 3.127e-06 7.831e-06 0.0002598 0.001972 0.007071 0.08891 NaN 1
2 1422 2.63e-06 6.222e-06 0.00013 0.001925 0.007029 0.03327 NaN 0
4 2805 2.293e-06 1.081e-05 6.493e-05 0.002235 0.006624 0.2111 NaN 0
8 5543 2.804e-06 2.056e-05 3.252e-05 0.002252 0.005205 0.2133 NaN 0
EOD
$dt_1e_4_velocity_iterations << EOD
1 510.5 3.151e-06 7.665e-06 0.0002608 0.00197 0.007052 0.1009 NaN 0
2 543.9 3.122e-06 7.741e-06 0.0002602 0.001972 0.007066 0.09807 NaN 0
4 592.7 3.114e-06 7.826e-06 0.0002599 0.001972 0.007077 0.09476 NaN 0
8 683.7 3.124e-06 7.741e-06 0.0002598 0.001971 0.007073 0.0905 NaN 0
10 711.5 3.127e-06 7.831e-06 0.0002598 0.001972 0.007071 0.08891 NaN 1
EOD
$dt_1e_4_position_iterations << EOD
0 433.5 5.7e-05 0.0001628 0.0002603 0.00204 0.007168 0.1194 NaN 0
1 580.6 3.442e-06 8.27e-06 0.0002599 0.001989 0.007068 0.09492 NaN 0
2 711.5 3.127e-06 7.831e-06 0.0002598 0.001972 0.007071 0.08891 NaN 1
EOD
$dt_1e_4_default << EOD
0 711.5 3.127e-06 7.831e-06 0.0002598 0.001972 0.007071 0.08891 NaN 1
EOD
set output 'dt-1e-4.png'
set multiplot layout 2,3 title 'dt-1e-4: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $dt_1e_4_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $dt_1e_4_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $dt_1e_4_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $dt_1e_4_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $dt_1e_4_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $dt_1e_4_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$mass_range_substeps << EOD
1 411.4 0.542 3.138 17.54 4.885 1.975 1.119e+06 NaN 1
2 813 0.2623 2.296 19.81 2.865 1.629 7.82e+05 NaN 0
4 1611 0.09748 0.9961 13.23 0.966 1.142 5.498e+05 NaN 0
8 3287 0.03262 0.4213 9.299 0.9273 1.157 4.024e+05 NaN 0
EOD
$mass_range_velocity_iterations << EOD
1 296.4 0.5078 2.748 15.93 4.562 1.878 1.164e+06 NaN 0
2 306.6 0.5426 3.005 17.12 4.87 1.958 1.128e+06 NaN 0
4 328.4 0.5421 3.127 17.5 4.885 1.975 1.12e+06 NaN 0
8 382.7 0.542 3.138 17.54 4.885 1.975 1.119e+06 NaN 0
10 411.4 0.542 3.138 17.54 4.885 1.975 1.119e+06 NaN 1
EOD
$mass_range_position_iterations << EOD
0 231.6 1.099 4.607 13.15 7.285 1.847 1.546e+06 NaN 0
1 322.4 1.373 8.629 22.13 7.295 1.757 1.168e+06 NaN 0
2 411.4 0.542 3.138 17.54 4.885 1.975 1.119e+06 NaN 1
EOD
$mass_range_default << EOD
0 411.4 0.542 3.138 17.54 4.885 1.975 1.119e+06 NaN 1
EOD
set output 'mass-range.png'
set multiplot layout 2,3 title 'mass-range: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $mass_range_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $mass_range_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $mass_range_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $mass_range_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $mass_range_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $mass_range_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$mass_range_hanging_substeps << EOD
1 406.1 0.2633 1.508 1.402 0.6815 0.5778 8.912e+05 NaN 1
2 814 0.252 1.623 1.869 0.5129 0.5539 4.459e+05 NaN 0
4 1629 0.2487 1.799 1.738 0.3805 0.5275 2.239e+05 NaN 0
8 3226 0.2443 1.736 4.2 0.2344 0.417 1.167e+05 NaN 0
EOD
$mass_range_hanging_velocity_iterations << EOD
1 295.8 0.3598 2.243 1.824 0.8292 0.6119 8.911e+05 NaN 0
2 312.3 0.314 2.057 1.369 0.7723 0.598 8.911e+05 NaN 0
4 341.1 0.2835 1.741 1.167 0.7178 0.591 8.912e+05 NaN 0
8 388.7 0.2667 1.613 1.275 0.6794 0.58 8.912e+05 NaN 0
10 406.1 0.2633 1.508 1.402 0.6815 0.5778 8.912e+05 NaN 1
EOD
$mass_range_hanging_position_iterations << EOD
0 236.7 0.2615 1.532 1.656 0.6767 0.5848 8.911e+05 NaN 0
1 320.6 0.2603 1.561 1.451 0.6898 0.5793 8.912e+05 NaN 0
2 406.1 0.2633 1.508 1.402 0.6815 0.5778 8.912e+05 NaN 1
EOD
$mass_range_hanging_default << EOD
0 406.1 0.2633 1.508 1.402 0.6815 0.5778 8.912e+05 NaN 1
EOD
set output 'mass-range-hanging.png'
set multiplot layout 2,3 title 'mass-range-hanging: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $mass_range_hanging_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $mass_range_hanging_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $mass_range_hanging_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $mass_range_hanging_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $mass_range_hanging_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $mass_range_hanging_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$far_1e4_substeps << EOD
1 710.6 0.006056 0.01734 0.04339 0.07506 0.024 24.89 NaN 1
2 1392 0.002982 0.008446 0.02158 0.03179 0.01566 11.44 NaN 0
4 2747 0.002282 0.008564 0.01125 0.01386 0.02111 5.294 NaN 0
8 5450 0.003043 0.01063 0.006116 0.01567 0.03441 2.655 NaN 0
EOD
$far_1e4_velocity_iterations << EOD
1 488.8 0.02176 0.06065 0.1062 0.3111 0.1399 61.51 NaN 0
2 502.9 0.01349 0.03575 0.05821 0.1884 0.06845 43.58 NaN 0
4 553.7 0.009157 0.02332 0.04904 0.1218 0.04188 33.08 NaN 0
8 639.4 0.006614 0.01815 0.04391 0.08247 0.02671 26.3 NaN 0
10 710.6 0.006056 0.01734 0.04339 0.07506 0.024 24.89 NaN 1
EOD
$far_1e4_position_iterations << EOD
0 414.4 0.007126 0.0249 0.04752 0.07433 0.02736 26.93 NaN 0
1 550.9 0.006281 0.01844 0.04379 0.07586 0.02371 25.42 NaN 0
2 710.6 0.006056 0.01734 0.04339 0.07506 0.024 24.89 NaN 1
EOD
$far_1e4_default << EOD
0 710.6 0.006056 0.01734 0.04339 0.07506 0.024 24.89 NaN 1
EOD
set output 'far-1e4.png'
set multiplot layout 2,3 title 'far-1e4: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $far_1e4_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $far_1e4_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $far_1e4_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $far_1e4_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $far_1e4_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $far_1e4_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$chain16_r1000_substeps << EOD
1 701.5 0.03406 0.1224 0.2985 0.5814 0.3068 1769 NaN 1
2 1373 0.02625 0.08994 0.2528 0.4306 0.173 3069 NaN 0
4 2711 0.01343 0.04133 0.09186 0.218 0.08325 4077 NaN 0
8 5412 0.003423 0.007775 0.01029 0.05499 0.03082 981.7 NaN 0
EOD
$chain16_r1000_velocity_iterations << EOD
1 482.5 0.04831 0.1288 0.1969 0.9278 0.4722 1141 NaN 0
2 513.7 0.03984 0.107 0.1528 0.796 0.4151 1306 NaN 0
4 560.2 0.03581 0.1129 0.3329 0.6855 0.3636 1630 NaN 0
8 656.2 0.03445 0.1247 0.3165 0.6031 0.32 1723 NaN 0
10 701.5 0.03406 0.1224 0.2985 0.5814 0.3068 1769 NaN 1
EOD
$chain16_r1000_position_iterations << EOD
0 407.4 0.03734 0.1785 0.3453 0.5852 0.3124 1606 NaN 0
1 558.4 0.03429 0.1342 0.3274 0.5829 0.3099 1675 NaN 0
2 701.5 0.03406 0.1224 0.2985 0.5814 0.3068 1769 NaN 1
EOD
$chain16_r1000_default << EOD
0 701.5 0.03406 0.1224 0.2985 0.5814 0.3068 1769 NaN 1
EOD
set output 'chain16-r1000.png'
set multiplot layout 2,3 title 'chain16-r1000: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $chain16_r1000_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $chain16_r1000_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $chain16_r1000_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $chain16_r1000_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $chain16_r1000_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $chain16_r1000_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$chain64_substeps << EOD
1 2986 0.00544 0.01668 0.01637 0.2438 0.1077 131.1 NaN 1
2 5957 0.001565 0.004718 0.005285 0.07465 0.03267 47.21 NaN 0
4 1.206e+04 0.0004628 0.001427 0.001822 0.02094 0.01258 18.79 NaN 0
8 2.429e+04 0.0001479 0.0004778 0.0007851 0.005407 0.00559 8.14 NaN 0
EOD
$chain64_velocity_iterations << EOD
1 2029 0.01915 0.08694 0.07609 0.6444 0.3136 253 NaN 0
2 2137 0.01454 0.05765 0.04447 0.5653 0.2611 260.5 NaN 0
4 2336 0.01029 0.03716 0.02871 0.4347 0.1984 225.1 NaN 0
8 2766 0.006457 0.02037 0.01863 0.2864 0.1277 150.7 NaN 0
10 2986 0.00544 0.01668 0.01637 0.2438 0.1077 131.1 NaN 1
EOD
$chain64_position_iterations << EOD
0 1808 0.005681 0.01694 0.01811 0.2463 0.1126 137.4 NaN 0
1 2442 0.005505 0.01717 0.01675 0.245 0.1093 132.8 NaN 0
2 2986 0.00544 0.01668 0.01637 0.2438 0.1077 131.1 NaN 1
EOD
$chain64_default << EOD
0 2986 0.00544 0.01668 0.01637 0.2438 0.1077 131.1 NaN 1
EOD
set output 'chain64.png'
set multiplot layout 2,3 title 'chain64: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $chain64_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $chain64_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $chain64_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $chain64_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $chain64_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $chain64_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
