# Error against ns per world-step, one curve per knob: written by
# ./build/tools/manyworlds sweep --scenes spin-unstable,flywheel,singular-hinge-90,singular-hinge-180,singular-fixed-90,singular-fixed-180,singular-slider-90,singular-rackpinion,singular-swingtwist,dt-1/15,dt-1e-4,mass-range,mass-range-hanging,far-1e4,chain16-r1000,chain64 --worlds 256 --passes 1 --solver exact --out docs/accuracy/stress-exact --overwrite
# Run: gnuplot sweep.gp (in this directory).
set terminal pngcairo noenhanced size 1500,900 font ',10'
set logscale xy
set grid
set format y '%.0e'
set key below horizontal
set xlabel 'ns per world-step (256 worlds, 1 thread(s), AVX2)'
$spin_unstable_substeps << EOD
1 18.32 0 0 0 0 2.727e-06 4.597e-08 NaN 1
2 28.36 0 0 0 0 8.518e-07 9.265e-08 NaN 0
4 48.25 0 0 0 0 6.444e-07 1.714e-07 NaN 0
8 87.58 0 0 0 0 1.885e-07 5.714e-07 NaN 0
EOD
$spin_unstable_velocity_iterations << EOD
10 18.32 0 0 0 0 2.727e-06 4.597e-08 NaN 1
EOD
$spin_unstable_position_iterations << EOD
0 18.36 0 0 0 0 2.727e-06 4.597e-08 NaN 0
1 18.39 0 0 0 0 2.727e-06 4.597e-08 NaN 0
2 18.32 0 0 0 0 2.727e-06 4.597e-08 NaN 1
4 18.33 0 0 0 0 2.727e-06 4.597e-08 NaN 0
10 18.33 0 0 0 0 2.727e-06 4.597e-08 NaN 0
30 18.35 0 0 0 0 2.727e-06 4.597e-08 NaN 0
EOD
$spin_unstable_default << EOD
0 18.32 0 0 0 0 2.727e-06 4.597e-08 NaN 1
EOD
$spin_unstable_grid << EOD
0 18.36 0 0 0 0 2.727e-06 4.597e-08 NaN 0
0 18.39 0 0 0 0 2.727e-06 4.597e-08 NaN 0
0 18.32 0 0 0 0 2.727e-06 4.597e-08 NaN 1
0 18.33 0 0 0 0 2.727e-06 4.597e-08 NaN 0
0 18.33 0 0 0 0 2.727e-06 4.597e-08 NaN 0
0 18.35 0 0 0 0 2.727e-06 4.597e-08 NaN 0
0 28.46 0 0 0 0 8.518e-07 9.265e-08 NaN 0
0 28.37 0 0 0 0 8.518e-07 9.265e-08 NaN 0
0 28.36 0 0 0 0 8.518e-07 9.265e-08 NaN 0
0 28.36 0 0 0 0 8.518e-07 9.265e-08 NaN 0
0 28.43 0 0 0 0 8.518e-07 9.265e-08 NaN 0
0 28.46 0 0 0 0 8.518e-07 9.265e-08 NaN 0
0 48.2 0 0 0 0 6.444e-07 1.714e-07 NaN 0
0 48.17 0 0 0 0 6.444e-07 1.714e-07 NaN 0
0 48.25 0 0 0 0 6.444e-07 1.714e-07 NaN 0
0 48.22 0 0 0 0 6.444e-07 1.714e-07 NaN 0
0 48.18 0 0 0 0 6.444e-07 1.714e-07 NaN 0
0 48.19 0 0 0 0 6.444e-07 1.714e-07 NaN 0
0 87.63 0 0 0 0 1.885e-07 5.714e-07 NaN 0
0 87.62 0 0 0 0 1.885e-07 5.714e-07 NaN 0
0 87.58 0 0 0 0 1.885e-07 5.714e-07 NaN 0
0 87.53 0 0 0 0 1.885e-07 5.714e-07 NaN 0
0 94.09 0 0 0 0 1.885e-07 5.714e-07 NaN 0
0 87.5 0 0 0 0 1.885e-07 5.714e-07 NaN 0
EOD
set output 'spin-unstable.png'
set multiplot layout 1,3 title 'spin-unstable: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'trajectory error RMS (rad)'
plot $spin_unstable_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spin_unstable_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spin_unstable_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spin_unstable_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spin_unstable_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spin_unstable_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spin_unstable_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spin_unstable_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $spin_unstable_grid using 2:8 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spin_unstable_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spin_unstable_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spin_unstable_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spin_unstable_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spin_unstable_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spin_unstable_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spin_unstable_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$flywheel_substeps << EOD
1 111.1 0 0 2.436e-09 0 1.151e-06 0 NaN 1
2 351.1 0 0 1.218e-09 0 1.563e-06 0 NaN 0
4 424.5 0 0 6.091e-10 0 1.719e-06 0 NaN 0
8 1274 0 0 3.045e-10 0 1.39e-06 0 NaN 0
EOD
$flywheel_velocity_iterations << EOD
10 111.1 0 0 2.436e-09 0 1.151e-06 0 NaN 1
EOD
$flywheel_position_iterations << EOD
0 95.46 0 0 2.436e-09 0 1.151e-06 0 NaN 0
1 109.5 0 0 2.436e-09 0 1.151e-06 0 NaN 0
2 111.1 0 0 2.436e-09 0 1.151e-06 0 NaN 1
4 109 0 0 2.436e-09 0 1.151e-06 0 NaN 0
10 161.7 0 0 2.436e-09 0 1.151e-06 0 NaN 0
30 108.9 0 0 2.436e-09 0 1.151e-06 0 NaN 0
EOD
$flywheel_default << EOD
0 111.1 0 0 2.436e-09 0 1.151e-06 0 NaN 1
EOD
$flywheel_grid << EOD
0 95.46 0 0 2.436e-09 0 1.151e-06 0 NaN 0
0 109.5 0 0 2.436e-09 0 1.151e-06 0 NaN 0
0 111.1 0 0 2.436e-09 0 1.151e-06 0 NaN 1
0 109 0 0 2.436e-09 0 1.151e-06 0 NaN 0
0 161.7 0 0 2.436e-09 0 1.151e-06 0 NaN 0
0 108.9 0 0 2.436e-09 0 1.151e-06 0 NaN 0
0 183.3 0 0 1.218e-09 0 1.563e-06 0 NaN 0
0 268.7 0 0 1.218e-09 0 1.563e-06 0 NaN 0
0 351.1 0 0 1.218e-09 0 1.563e-06 0 NaN 0
0 214 0 0 1.218e-09 0 1.563e-06 0 NaN 0
0 213.7 0 0 1.218e-09 0 1.563e-06 0 NaN 0
0 210.9 0 0 1.218e-09 0 1.563e-06 0 NaN 0
0 386.2 0 0 6.091e-10 0 1.719e-06 0 NaN 0
0 499.4 0 0 6.091e-10 0 1.719e-06 0 NaN 0
0 424.5 0 0 6.091e-10 0 1.719e-06 0 NaN 0
0 457.8 0 0 6.091e-10 0 1.719e-06 0 NaN 0
0 440.7 0 0 6.091e-10 0 1.719e-06 0 NaN 0
0 416.3 0 0 6.091e-10 0 1.719e-06 0 NaN 0
0 781.9 0 0 3.045e-10 0 1.39e-06 0 NaN 0
0 892.7 0 0 3.045e-10 0 1.39e-06 0 NaN 0
0 1274 0 0 3.045e-10 0 1.39e-06 0 NaN 0
0 1055 0 0 3.045e-10 0 1.39e-06 0 NaN 0
0 1117 0 0 3.045e-10 0 1.39e-06 0 NaN 0
0 959.5 0 0 3.045e-10 0 1.39e-06 0 NaN 0
EOD
set output 'flywheel.png'
set multiplot layout 1,3 title 'flywheel: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $flywheel_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $flywheel_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $flywheel_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $flywheel_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $flywheel_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $flywheel_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $flywheel_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $flywheel_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $flywheel_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $flywheel_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $flywheel_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $flywheel_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $flywheel_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $flywheel_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $flywheel_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $flywheel_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_hinge_90_substeps << EOD
1 233.1 0.07369 0.5708 0 0 0.07369 0 NaN 1
2 622.1 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
4 1144 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
8 2123 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
EOD
$singular_hinge_90_velocity_iterations << EOD
1 128.7 0.07369 0.5708 0 0 0.07369 0 NaN 0
2 140.9 0.07369 0.5708 0 0 0.07369 0 NaN 0
4 160.9 0.07369 0.5708 0 0 0.07369 0 NaN 0
10 233.1 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_hinge_90_position_iterations << EOD
0 145.2 1.571 1.571 0 0 1.571 0 NaN 0
1 184.1 0.1569 1.071 0 0 0.1569 0 NaN 0
2 233.1 0.07369 0.5708 0 0 0.07369 0 NaN 1
4 244.6 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
10 419 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
30 877.2 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
EOD
$singular_hinge_90_default << EOD
0 233.1 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_hinge_90_grid << EOD
0 80.73 1.571 1.571 0 0 1.571 0 NaN 0
0 116.5 0.1569 1.071 0 0 0.1569 0 NaN 0
0 128.7 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 202.6 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 330.6 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 874.7 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 90.59 1.571 1.571 0 0 1.571 0 NaN 0
0 119.5 0.1569 1.071 0 0 0.1569 0 NaN 0
0 140.9 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 207.2 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 335.4 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 881.3 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 104.3 1.571 1.571 0 0 1.571 0 NaN 0
0 131.6 0.1569 1.071 0 0 0.1569 0 NaN 0
0 160.9 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 289.8 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 440.2 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1015 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 145.2 1.571 1.571 0 0 1.571 0 NaN 0
0 184.1 0.1569 1.071 0 0 0.1569 0 NaN 0
0 233.1 0.07369 0.5708 0 0 0.07369 0 NaN 1
0 244.6 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 419 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 877.2 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 255.8 1.571 1.571 0 0 1.571 0 NaN 0
0 353.1 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 390.7 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 547.8 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 975.4 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1927 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 229.5 1.571 1.571 0 0 1.571 0 NaN 0
0 225.3 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 269.2 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 368.4 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 691.9 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1783 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 217.5 1.571 1.571 0 0 1.571 0 NaN 0
0 246.6 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 480 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 536.4 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 801.5 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 2410 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 413.4 1.571 1.571 0 0 1.571 0 NaN 0
0 484.5 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 622.1 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 559.4 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 888.7 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1804 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 291.9 1.571 1.571 0 0 1.571 0 NaN 0
0 388.9 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 575.5 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1092 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1753 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 3590 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 337.6 1.571 1.571 0 0 1.571 0 NaN 0
0 460.9 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 563.5 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1088 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1834 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 4392 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 559.1 1.571 1.571 0 0 1.571 0 NaN 0
0 710.9 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 877.1 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1122 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1630 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 4913 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 883.8 1.571 1.571 0 0 1.571 0 NaN 0
0 1131 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 1144 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1276 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1800 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 4618 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 804.1 1.571 1.571 0 0 1.571 0 NaN 0
0 1155 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1391 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1505 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 3333 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 9317 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1133 1.571 1.571 0 0 1.571 0 NaN 0
0 981.8 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1324 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1528 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 4015 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1.035e+04 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1148 1.571 1.571 0 0 1.571 0 NaN 0
0 1317 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1605 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 2256 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 3369 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 9111 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1621 1.571 1.571 0 0 1.571 0 NaN 0
0 1349 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 2123 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 2919 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 4426 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 9957 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
EOD
set output 'singular-hinge-90.png'
set multiplot layout 1,3 title 'singular-hinge-90: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_hinge_90_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_hinge_90_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_90_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_90_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_90_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_90_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_90_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_90_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_hinge_90_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_hinge_90_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_90_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_90_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_90_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_90_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_90_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_90_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_hinge_90_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_hinge_90_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_90_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_90_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_90_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_90_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_90_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_90_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_hinge_180_substeps << EOD
1 252.4 0.3138 2.142 0 0 0.3138 0 NaN 1
2 654.7 0.1474 1.142 0 0 0.1474 0 NaN 0
4 1162 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
8 2443 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
EOD
$singular_hinge_180_velocity_iterations << EOD
1 142.4 0.3138 2.142 0 0 0.3138 0 NaN 0
2 147.2 0.3138 2.142 0 0 0.3138 0 NaN 0
4 284.8 0.3138 2.142 0 0 0.3138 0 NaN 0
10 252.4 0.3138 2.142 0 0 0.3138 0 NaN 1
EOD
$singular_hinge_180_position_iterations << EOD
0 214 3.142 3.142 0 0 3.142 0 NaN 0
1 205.2 0.5163 2.642 0 0 0.5163 0 NaN 0
2 252.4 0.3138 2.142 0 0 0.3138 0 NaN 1
4 395.2 0.1474 1.142 0 0 0.1474 0 NaN 0
10 402.2 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
30 1028 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
EOD
$singular_hinge_180_default << EOD
0 252.4 0.3138 2.142 0 0 0.3138 0 NaN 1
EOD
$singular_hinge_180_grid << EOD
0 82.1 3.142 3.142 0 0 3.142 0 NaN 0
0 109.3 0.5163 2.642 0 0 0.5163 0 NaN 0
0 142.4 0.3138 2.142 0 0 0.3138 0 NaN 0
0 265.4 0.1474 1.142 0 0 0.1474 0 NaN 0
0 462.5 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1122 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 108.6 3.142 3.142 0 0 3.142 0 NaN 0
0 119.5 0.5163 2.642 0 0 0.5163 0 NaN 0
0 147.2 0.3138 2.142 0 0 0.3138 0 NaN 0
0 192.2 0.1474 1.142 0 0 0.1474 0 NaN 0
0 488.4 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1067 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 112.1 3.142 3.142 0 0 3.142 0 NaN 0
0 131.6 0.5163 2.642 0 0 0.5163 0 NaN 0
0 284.8 0.3138 2.142 0 0 0.3138 0 NaN 0
0 367.2 0.1474 1.142 0 0 0.1474 0 NaN 0
0 562.6 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1235 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 214 3.142 3.142 0 0 3.142 0 NaN 0
0 205.2 0.5163 2.642 0 0 0.5163 0 NaN 0
0 252.4 0.3138 2.142 0 0 0.3138 0 NaN 1
0 395.2 0.1474 1.142 0 0 0.1474 0 NaN 0
0 402.2 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1028 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 171.5 3.142 3.142 0 0 3.142 0 NaN 0
0 199.6 0.3138 2.142 0 0 0.3138 0 NaN 0
0 331.1 0.1474 1.142 0 0 0.1474 0 NaN 0
0 473.3 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 716.5 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 2168 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 172.9 3.142 3.142 0 0 3.142 0 NaN 0
0 226.4 0.3138 2.142 0 0 0.3138 0 NaN 0
0 407.7 0.1474 1.142 0 0 0.1474 0 NaN 0
0 484.8 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 670.2 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 2048 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 202.7 3.142 3.142 0 0 3.142 0 NaN 0
0 248.2 0.3138 2.142 0 0 0.3138 0 NaN 0
0 432.7 0.1474 1.142 0 0 0.1474 0 NaN 0
0 665.9 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 971.6 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 2497 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 385.4 3.142 3.142 0 0 3.142 0 NaN 0
0 537.1 0.3138 2.142 0 0 0.3138 0 NaN 0
0 654.7 0.1474 1.142 0 0 0.1474 0 NaN 0
0 719.4 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 781.6 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1764 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 304.6 3.142 3.142 0 0 3.142 0 NaN 0
0 381.7 0.1474 1.142 0 0 0.1474 0 NaN 0
0 488.9 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 699.8 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1958 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 4610 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 522 3.142 3.142 0 0 3.142 0 NaN 0
0 429.5 0.1474 1.142 0 0 0.1474 0 NaN 0
0 521.1 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 722.8 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1396 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 4054 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 386.3 3.142 3.142 0 0 3.142 0 NaN 0
0 482.3 0.1474 1.142 0 0 0.1474 0 NaN 0
0 610.8 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 815.5 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1431 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 4364 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 579 3.142 3.142 0 0 3.142 0 NaN 0
0 797.2 0.1474 1.142 0 0 0.1474 0 NaN 0
0 1162 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1466 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 2287 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 5045 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1007 3.142 3.142 0 0 3.142 0 NaN 0
0 990.9 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1248 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1384 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 3722 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 9347 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 666 3.142 3.142 0 0 3.142 0 NaN 0
0 836.7 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1125 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1503 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 3236 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 9716 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 788.2 3.142 3.142 0 0 3.142 0 NaN 0
0 948.8 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1918 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 2222 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 3935 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 9334 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1820 3.142 3.142 0 0 3.142 0 NaN 0
0 2140 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 2443 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1878 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 4176 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 8772 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
EOD
set output 'singular-hinge-180.png'
set multiplot layout 1,3 title 'singular-hinge-180: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_hinge_180_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_hinge_180_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_180_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_180_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_180_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_180_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_180_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_180_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_hinge_180_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_hinge_180_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_180_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_180_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_180_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_180_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_180_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_180_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_hinge_180_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_hinge_180_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_hinge_180_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_hinge_180_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_hinge_180_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_hinge_180_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_hinge_180_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_hinge_180_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_fixed_90_substeps << EOD
1 104.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
2 198.8 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
4 385 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
8 999.2 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
EOD
$singular_fixed_90_velocity_iterations << EOD
10 104.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_fixed_90_position_iterations << EOD
0 125.9 1.571 1.571 0 0 1.571 0 NaN 0
1 182.9 0.1569 1.071 0 0 0.1569 0 NaN 0
2 104.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
4 105 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
10 105.5 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
30 105.2 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
EOD
$singular_fixed_90_default << EOD
0 104.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_fixed_90_grid << EOD
0 125.9 1.571 1.571 0 0 1.571 0 NaN 0
0 182.9 0.1569 1.071 0 0 0.1569 0 NaN 0
0 104.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
0 105 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 105.5 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 105.2 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 166.1 1.571 1.571 0 0 1.571 0 NaN 0
0 197.1 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 198.8 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 204 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 203.4 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 291.5 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 470.7 1.571 1.571 0 0 1.571 0 NaN 0
0 391.6 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 385 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 395.4 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 398.2 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 386.7 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 888.6 1.571 1.571 0 0 1.571 0 NaN 0
0 1203 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 999.2 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 774.6 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 754.7 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 759 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
EOD
set output 'singular-fixed-90.png'
set multiplot layout 1,3 title 'singular-fixed-90: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_fixed_90_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_fixed_90_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_90_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_90_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_90_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_90_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_90_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_90_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_fixed_90_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_fixed_90_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_90_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_90_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_90_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_90_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_90_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_90_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_fixed_90_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_fixed_90_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_90_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_90_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_90_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_90_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_90_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_90_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_fixed_180_substeps << EOD
1 106.7 0.3138 2.142 0 0 0.3138 0 NaN 1
2 280.6 0.1474 1.142 0 0 0.1474 0 NaN 0
4 653.4 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
8 1071 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
EOD
$singular_fixed_180_velocity_iterations << EOD
10 106.7 0.3138 2.142 0 0 0.3138 0 NaN 1
EOD
$singular_fixed_180_position_iterations << EOD
0 125.7 3.142 3.142 0 0 3.142 0 NaN 0
1 108.2 0.5163 2.642 0 0 0.5163 0 NaN 0
2 106.7 0.3138 2.142 0 0 0.3138 0 NaN 1
4 107.2 0.1474 1.142 0 0 0.1474 0 NaN 0
10 107.8 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
30 137.1 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
EOD
$singular_fixed_180_default << EOD
0 106.7 0.3138 2.142 0 0 0.3138 0 NaN 1
EOD
$singular_fixed_180_grid << EOD
0 125.7 3.142 3.142 0 0 3.142 0 NaN 0
0 108.2 0.5163 2.642 0 0 0.5163 0 NaN 0
0 106.7 0.3138 2.142 0 0 0.3138 0 NaN 1
0 107.2 0.1474 1.142 0 0 0.1474 0 NaN 0
0 107.8 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 137.1 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 235.4 3.142 3.142 0 0 3.142 0 NaN 0
0 260.1 0.3138 2.142 0 0 0.3138 0 NaN 0
0 280.6 0.1474 1.142 0 0 0.1474 0 NaN 0
0 208.4 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 319.9 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 239.1 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 435.6 3.142 3.142 0 0 3.142 0 NaN 0
0 654.9 0.1474 1.142 0 0 0.1474 0 NaN 0
0 653.4 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 399.3 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 559.2 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 548.4 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 860.8 3.142 3.142 0 0 3.142 0 NaN 0
0 1071 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 1071 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 1065 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 1068 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 1068 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
EOD
set output 'singular-fixed-180.png'
set multiplot layout 1,3 title 'singular-fixed-180: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_fixed_180_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_fixed_180_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_180_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_180_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_180_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_180_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_180_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_180_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_fixed_180_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_fixed_180_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_180_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_180_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_180_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_180_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_180_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_180_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_fixed_180_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_fixed_180_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_fixed_180_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_fixed_180_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_fixed_180_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_fixed_180_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_fixed_180_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_fixed_180_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_slider_90_substeps << EOD
1 273.9 0.07369 0.5708 0 0 0.07369 0 NaN 1
2 460.7 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
4 903.6 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
8 1791 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
EOD
$singular_slider_90_velocity_iterations << EOD
1 234.5 0.07369 0.5708 0 0 0.07369 0 NaN 0
2 179 0.07369 0.5708 0 0 0.07369 0 NaN 0
4 189.7 0.07369 0.5708 0 0 0.07369 0 NaN 0
10 273.9 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_slider_90_position_iterations << EOD
0 154.5 1.571 1.571 0 0 1.571 0 NaN 0
1 199.3 0.1569 1.071 0 0 0.1569 0 NaN 0
2 273.9 0.07369 0.5708 0 0 0.07369 0 NaN 1
4 304.7 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
10 544.5 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
30 1946 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
EOD
$singular_slider_90_default << EOD
0 273.9 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_slider_90_grid << EOD
0 123.1 1.571 1.571 0 0 1.571 0 NaN 0
0 184.2 0.1569 1.071 0 0 0.1569 0 NaN 0
0 234.5 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 336 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 642.5 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1662 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 141.1 1.571 1.571 0 0 1.571 0 NaN 0
0 190.7 0.1569 1.071 0 0 0.1569 0 NaN 0
0 179 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 251.6 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 471.2 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1230 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 112.1 1.571 1.571 0 0 1.571 0 NaN 0
0 156.4 0.1569 1.071 0 0 0.1569 0 NaN 0
0 189.7 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 263.1 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 499.5 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1290 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 154.5 1.571 1.571 0 0 1.571 0 NaN 0
0 199.3 0.1569 1.071 0 0 0.1569 0 NaN 0
0 273.9 0.07369 0.5708 0 0 0.07369 0 NaN 1
0 304.7 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 544.5 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1946 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 281.1 1.571 1.571 0 0 1.571 0 NaN 0
0 259.1 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 320.5 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 468 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 920 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2860 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 185.7 1.571 1.571 0 0 1.571 0 NaN 0
0 296.3 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 378.9 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 490.5 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 994.3 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2742 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 217.8 1.571 1.571 0 0 1.571 0 NaN 0
0 317.1 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 374.5 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 516.9 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1034 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2541 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 313.7 1.571 1.571 0 0 1.571 0 NaN 0
0 638.7 0.07369 0.5708 0 0 0.07369 0 NaN 0
0 460.7 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 602 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1051 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2554 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 312.3 1.571 1.571 0 0 1.571 0 NaN 0
0 474.2 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 668.5 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 998.8 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2687 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 7392 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 523.1 1.571 1.571 0 0 1.571 0 NaN 0
0 775.6 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 1074 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1457 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2764 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 5743 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 432.3 1.571 1.571 0 0 1.571 0 NaN 0
0 915.4 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 1109 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1504 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2770 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 5419 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 637.4 1.571 1.571 0 0 1.571 0 NaN 0
0 835.9 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 903.6 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1395 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2203 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 6077 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1027 1.571 1.571 0 0 1.571 0 NaN 0
0 1002 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1476 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2390 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 6064 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1.379e+04 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 860.4 1.571 1.571 0 0 1.571 0 NaN 0
0 1162 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1559 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1999 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 3930 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1.162e+04 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1531 1.571 1.571 0 0 1.571 0 NaN 0
0 2040 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2672 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 3560 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 4107 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1.175e+04 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1174 1.571 1.571 0 0 1.571 0 NaN 0
0 1492 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1791 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2385 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 4719 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1.218e+04 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
EOD
set output 'singular-slider-90.png'
set multiplot layout 1,3 title 'singular-slider-90: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_slider_90_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_slider_90_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_slider_90_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_slider_90_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_slider_90_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_slider_90_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_slider_90_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_slider_90_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_slider_90_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_slider_90_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_slider_90_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_slider_90_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_slider_90_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_slider_90_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_slider_90_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_slider_90_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_slider_90_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_slider_90_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_slider_90_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_slider_90_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_slider_90_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_slider_90_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_slider_90_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_slider_90_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_rackpinion_substeps << EOD
1 629 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 1
2 1376 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
4 2420 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
8 3454 6.145e-07 1.791e-06 1.763e-08 0.0001132 0.001133 NaN 1.064e-06 0
EOD
$singular_rackpinion_velocity_iterations << EOD
1 359.9 0 0 0 0.1161 1.161 NaN 0 0
2 403.1 4.85e-08 1.936e-07 5.659e-08 0.001406 0.01406 NaN 8.401e-08 0
4 414.2 6.296e-08 3.158e-07 5.171e-08 0.0009077 0.009077 NaN 1.091e-07 0
10 629 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 1
EOD
$singular_rackpinion_position_iterations << EOD
0 577.5 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
1 493.1 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
2 629 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 1
4 724.4 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
10 675.1 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
30 664.4 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
EOD
$singular_rackpinion_default << EOD
0 629 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 1
EOD
$singular_rackpinion_grid << EOD
0 232.5 0 0 0 0.1161 1.161 NaN 0 0
0 392.3 0 0 0 0.1161 1.161 NaN 0 0
0 359.9 0 0 0 0.1161 1.161 NaN 0 0
0 409.9 0 0 0 0.1161 1.161 NaN 0 0
0 365.8 0 0 0 0.1161 1.161 NaN 0 0
0 359.8 0 0 0 0.1161 1.161 NaN 0 0
0 227.5 4.85e-08 1.936e-07 5.659e-08 0.001406 0.01406 NaN 8.401e-08 0
0 280.6 4.85e-08 1.936e-07 5.659e-08 0.001406 0.01406 NaN 8.401e-08 0
0 403.1 4.85e-08 1.936e-07 5.659e-08 0.001406 0.01406 NaN 8.401e-08 0
0 411.4 4.85e-08 1.936e-07 5.659e-08 0.001406 0.01406 NaN 8.401e-08 0
0 413.7 4.85e-08 1.936e-07 5.659e-08 0.001406 0.01406 NaN 8.401e-08 0
0 415.8 4.85e-08 1.936e-07 5.659e-08 0.001406 0.01406 NaN 8.401e-08 0
0 388.5 6.296e-08 3.158e-07 5.171e-08 0.0009077 0.009077 NaN 1.091e-07 0
0 420.6 6.296e-08 3.158e-07 5.171e-08 0.0009077 0.009077 NaN 1.091e-07 0
0 414.2 6.296e-08 3.158e-07 5.171e-08 0.0009077 0.009077 NaN 1.091e-07 0
0 371.2 6.296e-08 3.158e-07 5.171e-08 0.0009077 0.009077 NaN 1.091e-07 0
0 337.5 6.296e-08 3.158e-07 5.171e-08 0.0009077 0.009077 NaN 1.091e-07 0
0 320.8 6.296e-08 3.158e-07 5.171e-08 0.0009077 0.009077 NaN 1.091e-07 0
0 577.5 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
0 493.1 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
0 629 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 1
0 724.4 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
0 675.1 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
0 664.4 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
0 588.7 0 0 0 0.1161 1.161 NaN 0 0
0 822.4 0 0 0 0.1161 1.161 NaN 0 0
0 777.9 0 0 0 0.1161 1.161 NaN 0 0
0 771.1 0 0 0 0.1161 1.161 NaN 0 0
0 495.9 0 0 0 0.1161 1.161 NaN 0 0
0 565.8 0 0 0 0.1161 1.161 NaN 0 0
0 466.8 2.202e-07 1.111e-06 5.133e-08 0.0009532 0.009533 NaN 3.814e-07 0
0 557.5 2.202e-07 1.111e-06 5.133e-08 0.0009532 0.009533 NaN 3.814e-07 0
0 760.8 2.202e-07 1.111e-06 5.133e-08 0.0009532 0.009533 NaN 3.814e-07 0
0 551 2.202e-07 1.111e-06 5.133e-08 0.0009532 0.009533 NaN 3.814e-07 0
0 547.8 2.202e-07 1.111e-06 5.133e-08 0.0009532 0.009533 NaN 3.814e-07 0
0 542.5 2.202e-07 1.111e-06 5.133e-08 0.0009532 0.009533 NaN 3.814e-07 0
0 522.1 1.519e-07 8.803e-07 3.854e-08 0.0008942 0.008942 NaN 2.631e-07 0
0 1033 1.519e-07 8.803e-07 3.854e-08 0.0008942 0.008942 NaN 2.631e-07 0
0 1031 1.519e-07 8.803e-07 3.854e-08 0.0008942 0.008942 NaN 2.631e-07 0
0 986 1.519e-07 8.803e-07 3.854e-08 0.0008942 0.008942 NaN 2.631e-07 0
0 992.4 1.519e-07 8.803e-07 3.854e-08 0.0008942 0.008942 NaN 2.631e-07 0
0 995.4 1.519e-07 8.803e-07 3.854e-08 0.0008942 0.008942 NaN 2.631e-07 0
0 1179 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
0 1377 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
0 1376 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
0 1365 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
0 1177 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
0 1212 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
0 1230 0 0 0 0.1161 1.161 NaN 0 0
0 1562 0 0 0 0.1161 1.161 NaN 0 0
0 1573 0 0 0 0.1161 1.161 NaN 0 0
0 1606 0 0 0 0.1161 1.161 NaN 0 0
0 1256 0 0 0 0.1161 1.161 NaN 0 0
0 1271 0 0 0 0.1161 1.161 NaN 0 0
0 869.9 1.509e-07 6.636e-07 4.498e-08 0.0009012 0.009013 NaN 2.613e-07 0
0 1165 1.509e-07 6.636e-07 4.498e-08 0.0009012 0.009013 NaN 2.613e-07 0
0 1097 1.509e-07 6.636e-07 4.498e-08 0.0009012 0.009013 NaN 2.613e-07 0
0 1117 1.509e-07 6.636e-07 4.498e-08 0.0009012 0.009013 NaN 2.613e-07 0
0 1180 1.509e-07 6.636e-07 4.498e-08 0.0009012 0.009013 NaN 2.613e-07 0
0 1794 1.509e-07 6.636e-07 4.498e-08 0.0009012 0.009013 NaN 2.613e-07 0
0 1111 3.274e-07 1.231e-06 3.219e-08 0.0006368 0.006368 NaN 5.67e-07 0
0 1234 3.274e-07 1.231e-06 3.219e-08 0.0006368 0.006368 NaN 5.67e-07 0
0 1230 3.274e-07 1.231e-06 3.219e-08 0.0006368 0.006368 NaN 5.67e-07 0
0 1242 3.274e-07 1.231e-06 3.219e-08 0.0006368 0.006368 NaN 5.67e-07 0
0 1274 3.274e-07 1.231e-06 3.219e-08 0.0006368 0.006368 NaN 5.67e-07 0
0 1270 3.274e-07 1.231e-06 3.219e-08 0.0006368 0.006368 NaN 5.67e-07 0
0 2268 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
0 2497 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
0 2420 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
0 2426 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
0 2550 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
0 1805 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
0 1548 0 0 0 0.1161 1.161 NaN 0 0
0 1907 0 0 0 0.1161 1.161 NaN 0 0
0 2338 0 0 0 0.1161 1.161 NaN 0 0
0 3239 0 0 0 0.1161 1.161 NaN 0 0
0 2281 0 0 0 0.1161 1.161 NaN 0 0
0 1999 0 0 0 0.1161 1.161 NaN 0 0
0 1752 3.966e-07 1.265e-06 3.998e-08 0.0004324 0.004324 NaN 6.868e-07 0
0 2201 3.966e-07 1.265e-06 3.998e-08 0.0004324 0.004324 NaN 6.868e-07 0
0 2371 3.966e-07 1.265e-06 3.998e-08 0.0004324 0.004324 NaN 6.868e-07 0
0 2523 3.966e-07 1.265e-06 3.998e-08 0.0004324 0.004324 NaN 6.868e-07 0
0 2197 3.966e-07 1.265e-06 3.998e-08 0.0004324 0.004324 NaN 6.868e-07 0
0 2751 3.966e-07 1.265e-06 3.998e-08 0.0004324 0.004324 NaN 6.868e-07 0
0 2177 7.957e-07 2.376e-06 4.78e-08 0.0001912 0.001914 NaN 1.378e-06 0
0 2728 7.957e-07 2.376e-06 4.78e-08 0.0001912 0.001914 NaN 1.378e-06 0
0 2546 7.957e-07 2.376e-06 4.78e-08 0.0001912 0.001914 NaN 1.378e-06 0
0 4097 7.957e-07 2.376e-06 4.78e-08 0.0001912 0.001914 NaN 1.378e-06 0
0 4075 7.957e-07 2.376e-06 4.78e-08 0.0001912 0.001914 NaN 1.378e-06 0
0 2734 7.957e-07 2.376e-06 4.78e-08 0.0001912 0.001914 NaN 1.378e-06 0
0 3387 6.145e-07 1.791e-06 1.763e-08 0.0001132 0.001133 NaN 1.064e-06 0
0 3387 6.145e-07 1.791e-06 1.763e-08 0.0001132 0.001133 NaN 1.064e-06 0
0 3454 6.145e-07 1.791e-06 1.763e-08 0.0001132 0.001133 NaN 1.064e-06 0
0 4305 6.145e-07 1.791e-06 1.763e-08 0.0001132 0.001133 NaN 1.064e-06 0
0 3395 6.145e-07 1.791e-06 1.763e-08 0.0001132 0.001133 NaN 1.064e-06 0
0 4083 6.145e-07 1.791e-06 1.763e-08 0.0001132 0.001133 NaN 1.064e-06 0
EOD
set output 'singular-rackpinion.png'
set multiplot layout 2,3 title 'singular-rackpinion: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_rackpinion_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_rackpinion_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_rackpinion_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_rackpinion_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $singular_rackpinion_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_rackpinion_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $singular_rackpinion_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_rackpinion_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_rackpinion_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_rackpinion_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'coupling error RMS (rad)'
plot $singular_rackpinion_grid using 2:9 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_rackpinion_substeps using 2:9 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_rackpinion_substeps using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_rackpinion_velocity_iterations using 2:9 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_rackpinion_velocity_iterations using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_rackpinion_position_iterations using 2:9 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_rackpinion_position_iterations using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_rackpinion_default using 2:9 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_swingtwist_substeps << EOD
1 236.2 0.3282 1.893 0 0 0.3282 0 NaN 1
2 317 0.1833 1.286 0 0 0.1833 0 NaN 0
4 535 0.07181 0.5482 0 0 0.0718 0 NaN 0
8 1547 0.01198 0.09275 0 0 0.01198 0 NaN 0
EOD
$singular_swingtwist_velocity_iterations << EOD
1 103.3 0.3282 1.893 0 0 0.3282 0 NaN 0
2 109.3 0.3282 1.893 0 0 0.3282 0 NaN 0
4 201.3 0.3282 1.893 0 0 0.3282 0 NaN 0
10 236.2 0.3282 1.893 0 0 0.3282 0 NaN 1
EOD
$singular_swingtwist_position_iterations << EOD
0 108.9 2.642 2.642 0 0 2.642 0 NaN 0
1 214.4 0.5146 2.254 0 0 0.5146 0 NaN 0
2 236.2 0.3282 1.893 0 0 0.3282 0 NaN 1
4 283.4 0.1833 1.286 0 0 0.1833 0 NaN 0
10 456.9 0.04579 0.3526 0 0 0.04579 0 NaN 0
30 911 0.0005268 0.00408 0 0 0.0005263 0 NaN 0
EOD
$singular_swingtwist_default << EOD
0 236.2 0.3282 1.893 0 0 0.3282 0 NaN 1
EOD
$singular_swingtwist_grid << EOD
0 62.46 2.642 2.642 0 0 2.642 0 NaN 0
0 84.52 0.5146 2.254 0 0 0.5146 0 NaN 0
0 103.3 0.3282 1.893 0 0 0.3282 0 NaN 0
0 143.4 0.1833 1.286 0 0 0.1833 0 NaN 0
0 270.8 0.04579 0.3526 0 0 0.04579 0 NaN 0
0 687.3 0.0005268 0.00408 0 0 0.0005263 0 NaN 0
0 68.12 2.642 2.642 0 0 2.642 0 NaN 0
0 90.47 0.5146 2.254 0 0 0.5146 0 NaN 0
0 109.3 0.3282 1.893 0 0 0.3282 0 NaN 0
0 149.2 0.1833 1.286 0 0 0.1833 0 NaN 0
0 298.1 0.04579 0.3526 0 0 0.04579 0 NaN 0
0 706.9 0.0005268 0.00408 0 0 0.0005263 0 NaN 0
0 110.9 2.642 2.642 0 0 2.642 0 NaN 0
0 100.2 0.5146 2.254 0 0 0.5146 0 NaN 0
0 201.3 0.3282 1.893 0 0 0.3282 0 NaN 0
0 254 0.1833 1.286 0 0 0.1833 0 NaN 0
0 414.6 0.04579 0.3526 0 0 0.04579 0 NaN 0
0 758.1 0.0005268 0.00408 0 0 0.0005263 0 NaN 0
0 108.9 2.642 2.642 0 0 2.642 0 NaN 0
0 214.4 0.5146 2.254 0 0 0.5146 0 NaN 0
0 236.2 0.3282 1.893 0 0 0.3282 0 NaN 1
0 283.4 0.1833 1.286 0 0 0.1833 0 NaN 0
0 456.9 0.04579 0.3526 0 0 0.04579 0 NaN 0
0 911 0.0005268 0.00408 0 0 0.0005263 0 NaN 0
0 137.4 2.642 2.642 0 0 2.642 0 NaN 0
0 190.1 0.3282 1.893 0 0 0.3282 0 NaN 0
0 282 0.1833 1.286 0 0 0.1833 0 NaN 0
0 412.7 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 743.4 0.004906 0.038 0 0 0.004906 0 NaN 0
0 1345 4.065e-06 5.058e-06 0 0 1.327e-07 0 NaN 0
0 125.9 2.642 2.642 0 0 2.642 0 NaN 0
0 158.7 0.3282 1.893 0 0 0.3282 0 NaN 0
0 199.5 0.1833 1.286 0 0 0.1833 0 NaN 0
0 280.6 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 534.7 0.004906 0.038 0 0 0.004906 0 NaN 0
0 1360 4.065e-06 5.058e-06 0 0 1.327e-07 0 NaN 0
0 145.3 2.642 2.642 0 0 2.642 0 NaN 0
0 192 0.3282 1.893 0 0 0.3282 0 NaN 0
0 308.5 0.1833 1.286 0 0 0.1833 0 NaN 0
0 305.7 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 562.3 0.004906 0.038 0 0 0.004906 0 NaN 0
0 1507 4.065e-06 5.058e-06 0 0 1.327e-07 0 NaN 0
0 208.9 2.642 2.642 0 0 2.642 0 NaN 0
0 255 0.3282 1.893 0 0 0.3282 0 NaN 0
0 317 0.1833 1.286 0 0 0.1833 0 NaN 0
0 376 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 742.9 0.004906 0.038 0 0 0.004906 0 NaN 0
0 1680 4.065e-06 5.058e-06 0 0 1.327e-07 0 NaN 0
0 221 2.642 2.642 0 0 2.642 0 NaN 0
0 477.5 0.1833 1.286 0 0 0.1833 0 NaN 0
0 405.5 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 576 0.01198 0.09275 0 0 0.01198 0 NaN 0
0 1054 5.67e-05 0.0004381 0 0 5.604e-05 0 NaN 0
0 3343 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
0 246.8 2.642 2.642 0 0 2.642 0 NaN 0
0 409.9 0.1833 1.286 0 0 0.1833 0 NaN 0
0 375.5 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 542 0.01198 0.09275 0 0 0.01198 0 NaN 0
0 1041 5.67e-05 0.0004381 0 0 5.604e-05 0 NaN 0
0 2923 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
0 282.7 2.642 2.642 0 0 2.642 0 NaN 0
0 343.4 0.1833 1.286 0 0 0.1833 0 NaN 0
0 426.9 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 588 0.01198 0.09275 0 0 0.01198 0 NaN 0
0 1356 5.67e-05 0.0004381 0 0 5.604e-05 0 NaN 0
0 2805 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
0 588.7 2.642 2.642 0 0 2.642 0 NaN 0
0 663.8 0.1833 1.286 0 0 0.1833 0 NaN 0
0 535 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 707.3 0.01198 0.09275 0 0 0.01198 0 NaN 0
0 1260 5.67e-05 0.0004381 0 0 5.604e-05 0 NaN 0
0 3060 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
0 429.1 2.642 2.642 0 0 2.642 0 NaN 0
0 589.1 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 697.8 0.01198 0.09275 0 0 0.01198 0 NaN 0
0 1063 0.0003372 0.002611 0 0 0.0003366 0 NaN 0
0 2104 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
0 7000 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
0 476.5 2.642 2.642 0 0 2.642 0 NaN 0
0 569.3 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 745.7 0.01198 0.09275 0 0 0.01198 0 NaN 0
0 1484 0.0003372 0.002611 0 0 0.0003366 0 NaN 0
0 2775 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
0 6111 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
0 795.1 2.642 2.642 0 0 2.642 0 NaN 0
0 955.8 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 1109 0.01198 0.09275 0 0 0.01198 0 NaN 0
0 1511 0.0003372 0.002611 0 0 0.0003366 0 NaN 0
0 2726 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
0 6839 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
0 1070 2.642 2.642 0 0 2.642 0 NaN 0
0 1268 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 1547 0.01198 0.09275 0 0 0.01198 0 NaN 0
0 2089 0.0003372 0.002611 0 0 0.0003366 0 NaN 0
0 3229 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
0 7590 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
EOD
set output 'singular-swingtwist.png'
set multiplot layout 1,3 title 'singular-swingtwist: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_swingtwist_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_swingtwist_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_swingtwist_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_swingtwist_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_swingtwist_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_swingtwist_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_swingtwist_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_swingtwist_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_swingtwist_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_swingtwist_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_swingtwist_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_swingtwist_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_swingtwist_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_swingtwist_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_swingtwist_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_swingtwist_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_swingtwist_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_swingtwist_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_swingtwist_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_swingtwist_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_swingtwist_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_swingtwist_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_swingtwist_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_swingtwist_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$dt_1_15_substeps << EOD
1 1481 0.001029 0.007699 0.09808 0.2022 0.1548 49.68 NaN 1
2 2797 3.826e-07 4.053e-06 0.06381 0.1008 0.09794 26.54 NaN 0
4 5771 1.232e-06 9.12e-06 0.02831 0.05176 0.03824 5.847 NaN 0
8 9637 3.964e-07 3.222e-06 0.01298 0.02184 0.01937 2.931 NaN 0
EOD
$dt_1_15_velocity_iterations << EOD
10 1481 0.001029 0.007699 0.09808 0.2022 0.1548 49.68 NaN 1
EOD
$dt_1_15_position_iterations << EOD
0 1060 0.02146 0.06803 0.1608 0.2178 0.1706 79.4 NaN 0
1 1633 0.03462 0.1688 0.313 0.3209 0.2665 136.3 NaN 0
2 1481 0.001029 0.007699 0.09808 0.2022 0.1548 49.68 NaN 1
4 1884 3.287e-06 3.103e-05 0.09817 0.2041 0.1575 47.51 NaN 0
10 1960 4.803e-07 4.34e-06 0.09817 0.2041 0.1575 47.51 NaN 0
30 2159 4.803e-07 4.34e-06 0.09817 0.2041 0.1575 47.51 NaN 0
EOD
$dt_1_15_default << EOD
0 1481 0.001029 0.007699 0.09808 0.2022 0.1548 49.68 NaN 1
EOD
$dt_1_15_grid << EOD
0 1060 0.02146 0.06803 0.1608 0.2178 0.1706 79.4 NaN 0
0 1633 0.03462 0.1688 0.313 0.3209 0.2665 136.3 NaN 0
0 1481 0.001029 0.007699 0.09808 0.2022 0.1548 49.68 NaN 1
0 1884 3.287e-06 3.103e-05 0.09817 0.2041 0.1575 47.51 NaN 0
0 1960 4.803e-07 4.34e-06 0.09817 0.2041 0.1575 47.51 NaN 0
0 2159 4.803e-07 4.34e-06 0.09817 0.2041 0.1575 47.51 NaN 0
0 1483 0.01197 0.04288 0.1113 0.1252 0.1199 44.58 NaN 0
0 2182 1.613e-05 9.828e-05 0.06379 0.1008 0.09787 26.57 NaN 0
0 2797 3.826e-07 4.053e-06 0.06381 0.1008 0.09794 26.54 NaN 0
0 3762 3.826e-07 4.053e-06 0.06381 0.1008 0.09794 26.54 NaN 0
0 2897 3.826e-07 4.053e-06 0.06381 0.1008 0.09794 26.54 NaN 0
0 3470 3.826e-07 4.053e-06 0.06381 0.1008 0.09794 26.54 NaN 0
0 3011 0.01358 0.06177 0.1303 0.1022 0.2045 23.85 NaN 0
0 4907 5.568e-06 4.696e-05 0.02831 0.05175 0.03822 5.847 NaN 0
0 5771 1.232e-06 9.12e-06 0.02831 0.05176 0.03824 5.847 NaN 0
0 5470 1.232e-06 9.12e-06 0.02831 0.05176 0.03824 5.847 NaN 0
0 5964 1.232e-06 9.12e-06 0.02831 0.05176 0.03824 5.847 NaN 0
0 5596 1.232e-06 9.12e-06 0.02831 0.05176 0.03824 5.847 NaN 0
0 6394 0.003651 0.01572 0.02278 0.03126 0.06643 4.675 NaN 0
0 1.008e+04 3.964e-07 3.222e-06 0.01298 0.02184 0.01937 2.931 NaN 0
0 9637 3.964e-07 3.222e-06 0.01298 0.02184 0.01937 2.931 NaN 0
0 9249 3.964e-07 3.222e-06 0.01298 0.02184 0.01937 2.931 NaN 0
0 9333 3.964e-07 3.222e-06 0.01298 0.02184 0.01937 2.931 NaN 0
0 9391 3.964e-07 3.222e-06 0.01298 0.02184 0.01937 2.931 NaN 0
EOD
set output 'dt-1_15.png'
set multiplot layout 2,3 title 'dt-1/15: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $dt_1_15_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1_15_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $dt_1_15_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1_15_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $dt_1_15_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1_15_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $dt_1_15_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1_15_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $dt_1_15_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1_15_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $dt_1_15_grid using 2:8 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1_15_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1_15_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1_15_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1_15_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1_15_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1_15_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1_15_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$dt_1e_4_substeps << EOD
1 1299 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 1
2 2067 2.159e-06 9.983e-06 0.003293 0.001914 0.006952 0.0453 NaN 0
4 4318 2.339e-06 1e-05 0.006452 0.002167 0.006699 0.1831 NaN 0
8 8035 2.475e-06 1.038e-05 0.01256 0.002382 0.005825 0.1913 NaN 0
EOD
$dt_1e_4_velocity_iterations << EOD
10 1299 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 1
EOD
$dt_1e_4_position_iterations << EOD
0 1092 5.75e-05 0.0001536 0.001689 0.002048 0.007224 0.07313 NaN 0
1 1173 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 0
2 1299 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 1
4 1271 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 0
10 1229 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 0
30 1224 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 0
EOD
$dt_1e_4_default << EOD
0 1299 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 1
EOD
$dt_1e_4_grid << EOD
0 1092 5.75e-05 0.0001536 0.001689 0.002048 0.007224 0.07313 NaN 0
0 1173 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 0
0 1299 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 1
0 1271 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 0
0 1229 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 0
0 1224 2.134e-06 1.008e-05 0.001684 0.002001 0.007002 0.05928 NaN 0
0 2111 0.0001202 0.0003225 0.003292 0.00199 0.007384 0.03866 NaN 0
0 2069 2.159e-06 9.983e-06 0.003293 0.001914 0.006952 0.0453 NaN 0
0 2067 2.159e-06 9.983e-06 0.003293 0.001914 0.006952 0.0453 NaN 0
0 2296 2.159e-06 9.983e-06 0.003293 0.001914 0.006952 0.0453 NaN 0
0 2076 2.159e-06 9.983e-06 0.003293 0.001914 0.006952 0.0453 NaN 0
0 2259 2.159e-06 9.983e-06 0.003293 0.001914 0.006952 0.0453 NaN 0
0 4189 0.0002041 0.0005865 0.006418 0.002104 0.007062 0.1912 NaN 0
0 4457 2.339e-06 1e-05 0.006452 0.002167 0.006699 0.1831 NaN 0
0 4318 2.339e-06 1e-05 0.006452 0.002167 0.006699 0.1831 NaN 0
0 4309 2.339e-06 1e-05 0.006452 0.002167 0.006699 0.1831 NaN 0
0 4207 2.339e-06 1e-05 0.006452 0.002167 0.006699 0.1831 NaN 0
0 4237 2.339e-06 1e-05 0.006452 0.002167 0.006699 0.1831 NaN 0
0 7832 0.0004901 0.001402 0.01248 0.002419 0.004786 0.1914 NaN 0
0 8073 2.475e-06 1.038e-05 0.01256 0.002382 0.005825 0.1913 NaN 0
0 8035 2.475e-06 1.038e-05 0.01256 0.002382 0.005825 0.1913 NaN 0
0 8227 2.475e-06 1.038e-05 0.01256 0.002382 0.005825 0.1913 NaN 0
0 8739 2.475e-06 1.038e-05 0.01256 0.002382 0.005825 0.1913 NaN 0
0 8535 2.475e-06 1.038e-05 0.01256 0.002382 0.005825 0.1913 NaN 0
EOD
set output 'dt-1e-4.png'
set multiplot layout 2,3 title 'dt-1e-4: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $dt_1e_4_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1e_4_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $dt_1e_4_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1e_4_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $dt_1e_4_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1e_4_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $dt_1e_4_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1e_4_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $dt_1e_4_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1e_4_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $dt_1e_4_grid using 2:8 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $dt_1e_4_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $dt_1e_4_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $dt_1e_4_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $dt_1e_4_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $dt_1e_4_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $dt_1e_4_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $dt_1e_4_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$mass_range_substeps << EOD
1 1162 0.03108 0.4227 6.175 2.13 1.727 7.191e+05 NaN 1
2 2065 0.009644 0.1844 5.357 1.414 1.338 4.739e+05 NaN 0
4 4404 3.001e-05 0.0005211 3.725 0.8709 1.094 2.953e+05 NaN 0
8 8790 1.349e-06 1.425e-05 1.111 0.8929 0.9722 2.445e+05 NaN 0
EOD
$mass_range_velocity_iterations << EOD
10 1162 0.03108 0.4227 6.175 2.13 1.727 7.191e+05 NaN 1
EOD
$mass_range_position_iterations << EOD
0 617.8 0.2837 1.144 7.024 2.806 1.946 1.25e+06 NaN 0
1 857.5 0.132 1.216 7.262 2.586 1.863 7.297e+05 NaN 0
2 1162 0.03108 0.4227 6.175 2.13 1.727 7.191e+05 NaN 1
4 1450 0.0004455 0.01089 5.687 2.013 1.671 7.186e+05 NaN 0
10 1099 1.277e-06 9.69e-06 5.688 2.013 1.671 7.186e+05 NaN 0
30 1055 1.277e-06 9.69e-06 5.688 2.013 1.671 7.186e+05 NaN 0
EOD
$mass_range_default << EOD
0 1162 0.03108 0.4227 6.175 2.13 1.727 7.191e+05 NaN 1
EOD
$mass_range_grid << EOD
0 617.8 0.2837 1.144 7.024 2.806 1.946 1.25e+06 NaN 0
0 857.5 0.132 1.216 7.262 2.586 1.863 7.297e+05 NaN 0
0 1162 0.03108 0.4227 6.175 2.13 1.727 7.191e+05 NaN 1
0 1450 0.0004455 0.01089 5.687 2.013 1.671 7.186e+05 NaN 0
0 1099 1.277e-06 9.69e-06 5.688 2.013 1.671 7.186e+05 NaN 0
0 1055 1.277e-06 9.69e-06 5.688 2.013 1.671 7.186e+05 NaN 0
0 1278 0.4855 2.505 7.244 3.991 1.797 7.868e+05 NaN 0
0 1565 0.06225 0.886 6.179 1.315 1.29 4.841e+05 NaN 0
0 2065 0.009644 0.1844 5.357 1.414 1.338 4.739e+05 NaN 0
0 2417 1.271e-06 8.615e-06 4.882 1.419 1.35 4.736e+05 NaN 0
0 2370 1.271e-06 8.615e-06 4.882 1.419 1.35 4.736e+05 NaN 0
0 2473 1.271e-06 8.615e-06 4.882 1.419 1.35 4.736e+05 NaN 0
0 2800 0.1677 0.6732 1.444 2.524 1.781 4.61e+05 NaN 0
0 3178 0.00719 0.1272 4.108 0.8481 1.071 2.962e+05 NaN 0
0 4404 3.001e-05 0.0005211 3.725 0.8709 1.094 2.953e+05 NaN 0
0 4334 1.254e-06 8.79e-06 3.722 0.8708 1.094 2.952e+05 NaN 0
0 4819 1.254e-06 8.79e-06 3.722 0.8708 1.094 2.952e+05 NaN 0
0 4505 1.254e-06 8.79e-06 3.722 0.8708 1.094 2.952e+05 NaN 0
0 5301 0.1182 0.4894 0.6287 2.235 1.728 3.61e+05 NaN 0
0 7311 0.0003418 0.005776 1.111 0.8917 0.9718 2.445e+05 NaN 0
0 8790 1.349e-06 1.425e-05 1.111 0.8929 0.9722 2.445e+05 NaN 0
0 8180 1.217e-06 9.184e-06 1.111 0.8929 0.9722 2.445e+05 NaN 0
0 7140 1.217e-06 9.184e-06 1.111 0.8929 0.9722 2.445e+05 NaN 0
0 8787 1.217e-06 9.184e-06 1.111 0.8929 0.9722 2.445e+05 NaN 0
EOD
set output 'mass-range.png'
set multiplot layout 2,3 title 'mass-range: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $mass_range_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $mass_range_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $mass_range_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $mass_range_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $mass_range_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $mass_range_grid using 2:8 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$mass_range_hanging_substeps << EOD
1 933.6 0.7802 3.729 11.61 3.033 1.345 3.309e+07 NaN 1
2 1903 0.1606 1.041 3.712 0.4644 0.6901 4.555e+06 NaN 0
4 5208 0.1731 1.019 4.506 0.5552 0.8837 6.22e+06 NaN 0
8 7415 0.1669 1.037 3.556 0.4759 0.6071 5.917e+06 NaN 0
EOD
$mass_range_hanging_velocity_iterations << EOD
10 933.6 0.7802 3.729 11.61 3.033 1.345 3.309e+07 NaN 1
EOD
$mass_range_hanging_position_iterations << EOD
0 437.2 0.2317 0.9965 1.966 0.7083 1.243 8.982e+05 NaN 0
1 711.9 0.2256 1.494 1.615 0.5079 0.5514 8.913e+05 NaN 0
2 933.6 0.7802 3.729 11.61 3.033 1.345 3.309e+07 NaN 1
4 1529 0.1798 1.079 1.885 0.4859 0.4257 4.273e+06 NaN 0
10 3862 0.2571 1.608 6.225 0.3739 0.6566 8.918e+05 NaN 0
30 8895 0.2461 1.505 7.386 0.6602 0.8607 8.918e+05 NaN 0
EOD
$mass_range_hanging_default << EOD
0 933.6 0.7802 3.729 11.61 3.033 1.345 3.309e+07 NaN 1
EOD
$mass_range_hanging_grid << EOD
0 437.2 0.2317 0.9965 1.966 0.7083 1.243 8.982e+05 NaN 0
0 711.9 0.2256 1.494 1.615 0.5079 0.5514 8.913e+05 NaN 0
0 933.6 0.7802 3.729 11.61 3.033 1.345 3.309e+07 NaN 1
0 1529 0.1798 1.079 1.885 0.4859 0.4257 4.273e+06 NaN 0
0 3862 0.2571 1.608 6.225 0.3739 0.6566 8.918e+05 NaN 0
0 8895 0.2461 1.505 7.386 0.6602 0.8607 8.918e+05 NaN 0
0 918.4 0.1317 0.6919 4.848 0.8205 0.8584 9.823e+06 NaN 0
0 1845 0.2407 1.535 1.434 0.6284 0.5928 4.457e+05 NaN 0
0 1903 0.1606 1.041 3.712 0.4644 0.6901 4.555e+06 NaN 0
0 3556 0.2182 1.234 4.39 0.7984 1.372 2.379e+06 NaN 0
0 7711 0.1694 1.033 1.722 0.5057 0.7488 3.17e+06 NaN 0
0 1.76e+04 0.1948 1.188 6.145 0.4493 0.5949 5.411e+05 NaN 0
0 1919 0.2638 1.307 8.185 0.8072 1.278 9.482e+06 NaN 0
0 3743 0.249 1.602 1.685 0.6435 0.8844 2.228e+05 NaN 0
0 5208 0.1731 1.019 4.506 0.5552 0.8837 6.22e+06 NaN 0
0 7686 0.1737 1.252 11.55 0.4774 0.6439 1.004e+07 NaN 0
0 1.54e+04 0.1728 1.129 3.789 0.5776 0.9209 2.363e+06 NaN 0
0 3.835e+04 0.2443 1.534 8.702 0.4835 0.7303 1.786e+06 NaN 0
0 4252 0.4418 1.217 7.28 0.9667 0.8099 2.214e+07 NaN 0
0 7132 0.2108 1.371 3.645 0.4214 0.5239 1.121e+05 NaN 0
0 7415 0.1669 1.037 3.556 0.4759 0.6071 5.917e+06 NaN 0
0 1.53e+04 0.4031 2.314 32.79 1.355 1.227 7.919e+07 NaN 0
0 2.898e+04 0.1594 0.9228 2.567 0.5853 0.8008 3.812e+06 NaN 0
0 7.286e+04 0.1678 1.123 4.917 0.4316 0.598 3.249e+06 NaN 0
EOD
set output 'mass-range-hanging.png'
set multiplot layout 2,3 title 'mass-range-hanging: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $mass_range_hanging_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_hanging_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $mass_range_hanging_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_hanging_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $mass_range_hanging_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_hanging_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $mass_range_hanging_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_hanging_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $mass_range_hanging_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_hanging_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $mass_range_hanging_grid using 2:8 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $mass_range_hanging_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $mass_range_hanging_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $mass_range_hanging_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $mass_range_hanging_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $mass_range_hanging_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $mass_range_hanging_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $mass_range_hanging_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$far_1e4_substeps << EOD
1 2275 0.0005679 0.001703 0.04926 0.05567 0.03889 8.38 NaN 1
2 4799 0.0005942 0.001897 0.09265 0.02604 0.02371 3.945 NaN 0
4 8641 0.000605 0.001804 0.1782 0.01961 0.04441 3.652 NaN 0
8 1.791e+04 0.000599 0.002071 0.3567 0.02313 0.08552 10.82 NaN 0
EOD
$far_1e4_velocity_iterations << EOD
10 2275 0.0005679 0.001703 0.04926 0.05567 0.03889 8.38 NaN 1
EOD
$far_1e4_position_iterations << EOD
0 1220 0.01052 0.05962 0.1209 0.08973 0.1718 20.07 NaN 0
1 1739 0.0005968 0.001684 0.04853 0.05709 0.03734 8.312 NaN 0
2 2275 0.0005679 0.001703 0.04926 0.05567 0.03889 8.38 NaN 1
4 3097 0.0005695 0.001802 0.05014 0.05735 0.03923 5.772 NaN 0
10 6702 0.0005738 0.001829 0.05089 0.05427 0.0433 8.1 NaN 0
30 1.957e+04 0.0005354 0.001539 0.05007 0.05839 0.0375 6.649 NaN 0
EOD
$far_1e4_default << EOD
0 2275 0.0005679 0.001703 0.04926 0.05567 0.03889 8.38 NaN 1
EOD
$far_1e4_grid << EOD
0 1220 0.01052 0.05962 0.1209 0.08973 0.1718 20.07 NaN 0
0 1739 0.0005968 0.001684 0.04853 0.05709 0.03734 8.312 NaN 0
0 2275 0.0005679 0.001703 0.04926 0.05567 0.03889 8.38 NaN 1
0 3097 0.0005695 0.001802 0.05014 0.05735 0.03923 5.772 NaN 0
0 6702 0.0005738 0.001829 0.05089 0.05427 0.0433 8.1 NaN 0
0 1.957e+04 0.0005354 0.001539 0.05007 0.05839 0.0375 6.649 NaN 0
0 1620 0.005211 0.01572 0.08798 0.03342 0.04857 4.777 NaN 0
0 2685 0.0005895 0.002305 0.08806 0.02564 0.03335 4.789 NaN 0
0 4799 0.0005942 0.001897 0.09265 0.02604 0.02371 3.945 NaN 0
0 6199 0.0005845 0.001733 0.09277 0.02777 0.02511 3.994 NaN 0
0 1.119e+04 0.0005799 0.001914 0.09408 0.02711 0.03091 5.222 NaN 0
0 2.798e+04 0.000558 0.001738 0.09528 0.02854 0.03955 3.061 NaN 0
0 4166 0.006887 0.02793 0.1766 0.01746 0.03688 3.503 NaN 0
0 5257 0.0006469 0.001722 0.1967 0.03836 0.1119 5.132 NaN 0
0 8641 0.000605 0.001804 0.1782 0.01961 0.04441 3.652 NaN 0
0 1.31e+04 0.0005773 0.001674 0.1835 0.02595 0.05913 8.411 NaN 0
0 2.545e+04 0.0005861 0.001686 0.1858 0.01709 0.04782 7.604 NaN 0
0 6.673e+04 0.0005697 0.001969 0.1863 0.02541 0.05176 6.5 NaN 0
0 7021 0.0184 0.07161 0.3445 0.05142 0.07145 14.33 NaN 0
0 1.351e+04 0.0006344 0.001778 0.3832 0.04399 0.1399 17.82 NaN 0
0 1.791e+04 0.000599 0.002071 0.3567 0.02313 0.08552 10.82 NaN 0
0 2.598e+04 0.0006349 0.00194 0.3688 0.03241 0.08624 14.49 NaN 0
0 4.832e+04 0.000593 0.001738 0.3742 0.03548 0.08662 19.33 NaN 0
0 1.266e+05 0.0005972 0.00164 0.388 0.04985 0.09415 32.45 NaN 0
EOD
set output 'far-1e4.png'
set multiplot layout 2,3 title 'far-1e4: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $far_1e4_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $far_1e4_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $far_1e4_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $far_1e4_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $far_1e4_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $far_1e4_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $far_1e4_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $far_1e4_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $far_1e4_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $far_1e4_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $far_1e4_grid using 2:8 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $far_1e4_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $far_1e4_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $far_1e4_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $far_1e4_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $far_1e4_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $far_1e4_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $far_1e4_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$chain16_r1000_substeps << EOD
1 1564 0.02871 0.151 0.2909 0.3075 0.2253 1318 NaN 1
2 3768 0.002785 0.04344 0.1424 0.03274 0.05983 726 NaN 0
4 6059 2.551e-06 9.863e-06 0.002229 0.02138 0.01368 240.3 NaN 0
8 9681 3.155e-06 9.941e-06 0.0008925 0.02551 0.01511 93.85 NaN 0
EOD
$chain16_r1000_velocity_iterations << EOD
10 1564 0.02871 0.151 0.2909 0.3075 0.2253 1318 NaN 1
EOD
$chain16_r1000_position_iterations << EOD
0 733.7 0.00139 0.00416 0.0114 0.05157 0.02621 1151 NaN 0
1 1168 0.04313 0.2431 0.4778 0.4332 0.2701 1117 NaN 0
2 1564 0.02871 0.151 0.2909 0.3075 0.2253 1318 NaN 1
4 1993 0.02266 0.1635 0.4709 0.2215 0.149 1238 NaN 0
10 3150 7.96e-06 7.972e-05 0.007312 0.04473 0.01876 899.9 NaN 0
30 3717 2.49e-06 9.739e-06 0.007366 0.04474 0.01842 902.9 NaN 0
EOD
$chain16_r1000_default << EOD
0 1564 0.02871 0.151 0.2909 0.3075 0.2253 1318 NaN 1
EOD
$chain16_r1000_grid << EOD
0 733.7 0.00139 0.00416 0.0114 0.05157 0.02621 1151 NaN 0
0 1168 0.04313 0.2431 0.4778 0.4332 0.2701 1117 NaN 0
0 1564 0.02871 0.151 0.2909 0.3075 0.2253 1318 NaN 1
0 1993 0.02266 0.1635 0.4709 0.2215 0.149 1238 NaN 0
0 3150 7.96e-06 7.972e-05 0.007312 0.04473 0.01876 899.9 NaN 0
0 3717 2.49e-06 9.739e-06 0.007366 0.04474 0.01842 902.9 NaN 0
0 2110 0.07941 0.3378 0.5657 0.4421 0.6955 438.6 NaN 0
0 2507 0.02771 0.185 0.3802 0.2822 0.1683 750.5 NaN 0
0 3768 0.002785 0.04344 0.1424 0.03274 0.05983 726 NaN 0
0 4384 1.768e-06 9.817e-06 0.004085 0.02593 0.01438 465.6 NaN 0
0 4424 1.746e-06 9.817e-06 0.004082 0.02593 0.01437 465.8 NaN 0
0 4486 1.746e-06 9.817e-06 0.004082 0.02593 0.01437 465.8 NaN 0
0 4307 0.07789 0.3333 0.423 0.3757 0.7588 226.2 NaN 0
0 5780 0.005921 0.05399 0.2057 0.0527 0.08484 1005 NaN 0
0 6059 2.551e-06 9.863e-06 0.002229 0.02138 0.01368 240.3 NaN 0
0 4749 2.551e-06 9.863e-06 0.002229 0.02138 0.01368 240.3 NaN 0
0 4716 2.551e-06 9.863e-06 0.002229 0.02138 0.01368 240.3 NaN 0
0 4960 2.551e-06 9.863e-06 0.002229 0.02138 0.01368 240.3 NaN 0
0 7531 0.0394 0.1826 0.2061 0.2968 0.39 421.4 NaN 0
0 9532 3.155e-06 9.941e-06 0.0008925 0.02551 0.01511 93.85 NaN 0
0 9681 3.155e-06 9.941e-06 0.0008925 0.02551 0.01511 93.85 NaN 0
0 8688 3.155e-06 9.941e-06 0.0008925 0.02551 0.01511 93.85 NaN 0
0 9339 3.155e-06 9.941e-06 0.0008925 0.02551 0.01511 93.85 NaN 0
0 7338 3.155e-06 9.941e-06 0.0008925 0.02551 0.01511 93.85 NaN 0
EOD
set output 'chain16-r1000.png'
set multiplot layout 2,3 title 'chain16-r1000: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $chain16_r1000_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r1000_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $chain16_r1000_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r1000_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $chain16_r1000_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r1000_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $chain16_r1000_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r1000_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $chain16_r1000_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r1000_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $chain16_r1000_grid using 2:8 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r1000_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r1000_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r1000_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r1000_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r1000_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r1000_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r1000_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$chain64_substeps << EOD
1 7876 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 1
2 1.656e+04 1.904e-07 1.99e-06 0.001501 0.02417 0.0125 20.09 NaN 0
4 2.86e+04 3.101e-07 8.3e-06 0.0007233 0.01026 0.004763 10.03 NaN 0
8 4.578e+04 1.31e-06 9.362e-06 0.000376 0.00387 0.001753 5.021 NaN 0
EOD
$chain64_velocity_iterations << EOD
10 7876 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 1
EOD
$chain64_position_iterations << EOD
0 5142 0.01232 0.11 0.1249 0.2574 0.26 83.55 NaN 0
1 7089 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 0
2 7876 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 1
4 6828 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 0
10 8533 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 0
30 8427 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 0
EOD
$chain64_default << EOD
0 7876 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 1
EOD
$chain64_grid << EOD
0 5142 0.01232 0.11 0.1249 0.2574 0.26 83.55 NaN 0
0 7089 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 0
0 7876 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 1
0 6828 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 0
0 8533 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 0
0 8427 2.946e-07 6.403e-06 0.005042 0.05012 0.02529 47.84 NaN 0
0 1.027e+04 0.003886 0.03518 0.052 0.07394 0.146 20.81 NaN 0
0 1.121e+04 1.904e-07 1.99e-06 0.001501 0.02417 0.0125 20.09 NaN 0
0 1.656e+04 1.904e-07 1.99e-06 0.001501 0.02417 0.0125 20.09 NaN 0
0 1.164e+04 1.904e-07 1.99e-06 0.001501 0.02417 0.0125 20.09 NaN 0
0 1.261e+04 1.904e-07 1.99e-06 0.001501 0.02417 0.0125 20.09 NaN 0
0 1.665e+04 1.904e-07 1.99e-06 0.001501 0.02417 0.0125 20.09 NaN 0
0 1.833e+04 0.0003062 0.001903 0.00204 0.01533 0.02801 11.86 NaN 0
0 2.412e+04 3.101e-07 8.3e-06 0.0007233 0.01026 0.004763 10.03 NaN 0
0 2.86e+04 3.101e-07 8.3e-06 0.0007233 0.01026 0.004763 10.03 NaN 0
0 2.834e+04 3.101e-07 8.3e-06 0.0007233 0.01026 0.004763 10.03 NaN 0
0 2.813e+04 3.101e-07 8.3e-06 0.0007233 0.01026 0.004763 10.03 NaN 0
0 2.958e+04 3.101e-07 8.3e-06 0.0007233 0.01026 0.004763 10.03 NaN 0
0 3.774e+04 0.0001163 0.000465 0.000425 0.005952 0.009164 5.828 NaN 0
0 4.078e+04 1.31e-06 9.362e-06 0.000376 0.00387 0.001753 5.021 NaN 0
0 4.578e+04 1.31e-06 9.362e-06 0.000376 0.00387 0.001753 5.021 NaN 0
0 4.441e+04 1.31e-06 9.362e-06 0.000376 0.00387 0.001753 5.021 NaN 0
0 4.516e+04 1.31e-06 9.362e-06 0.000376 0.00387 0.001753 5.021 NaN 0
0 3.959e+04 1.31e-06 9.362e-06 0.000376 0.00387 0.001753 5.021 NaN 0
EOD
set output 'chain64.png'
set multiplot layout 2,3 title 'chain64: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $chain64_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain64_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $chain64_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain64_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $chain64_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain64_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $chain64_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain64_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $chain64_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain64_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $chain64_grid using 2:8 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain64_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain64_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain64_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain64_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain64_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain64_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain64_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
