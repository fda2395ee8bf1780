# Error against ns per world-step, one curve per knob: written by
# ./build/tools/manyworlds sweep --scenes spring-0.1,spring-0.25,spring-0.5,spring-1.0,singular-cone --worlds 256 --passes 2 --solver exact --out docs/accuracy/stress-exact-more --overwrite
# Run: gnuplot sweep.gp (in this directory).
set terminal pngcairo noenhanced size 1500,900 font ',10'
set logscale xy
set grid
set format y '%.0e'
set key below horizontal
set xlabel 'ns per world-step (256 worlds, 1 thread(s), AVX2)'
$spring_0_1_substeps << EOD
1 31.12 0.2865 0.9102 5.534 0.4506 0 NaN NaN 1
2 52.52 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
4 94.7 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
8 179.2 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
EOD
$spring_0_1_velocity_iterations << EOD
1 27.05 1 1 0 1.191 0 NaN NaN 0
2 28.83 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
4 31.26 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
10 31.12 0.2865 0.9102 5.534 0.4506 0 NaN NaN 1
EOD
$spring_0_1_position_iterations << EOD
0 30.25 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
1 30.82 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
2 31.12 0.2865 0.9102 5.534 0.4506 0 NaN NaN 1
4 31.01 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
10 31.16 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
30 31.08 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
EOD
$spring_0_1_default << EOD
0 31.12 0.2865 0.9102 5.534 0.4506 0 NaN NaN 1
EOD
$spring_0_1_grid << EOD
0 25.86 1 1 0 1.191 0 NaN NaN 0
0 27.02 1 1 0 1.191 0 NaN NaN 0
0 27.05 1 1 0 1.191 0 NaN NaN 0
0 27.09 1 1 0 1.191 0 NaN NaN 0
0 27.07 1 1 0 1.191 0 NaN NaN 0
0 27.05 1 1 0 1.191 0 NaN NaN 0
0 28.03 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 28.51 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 28.83 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 29.03 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 28.89 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 28.92 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 30.29 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 31.01 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 31.26 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 31.14 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 31.05 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 31.12 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 30.25 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 30.82 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 31.12 0.2865 0.9102 5.534 0.4506 0 NaN NaN 1
0 31.01 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 31.16 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 31.08 0.2865 0.9102 5.534 0.4506 0 NaN NaN 0
0 43.72 1 1 0 1.191 0 NaN NaN 0
0 44.89 1 1 0 1.191 0 NaN NaN 0
0 45.68 1 1 0 1.191 0 NaN NaN 0
0 44.91 1 1 0 1.191 0 NaN NaN 0
0 44.86 1 1 0 1.191 0 NaN NaN 0
0 44.87 1 1 0 1.191 0 NaN NaN 0
0 46.81 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 47.95 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 48.18 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 48.14 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 48.27 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 48.25 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 50.82 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 51.88 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 51.95 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 51.89 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 52.03 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 51.89 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 51.41 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 52.35 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 52.52 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 52.61 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 52.62 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 52.6 0.3933 0.9289 7.563 0.3072 0 NaN NaN 0
0 77.59 1 1 0 1.191 0 NaN NaN 0
0 80.23 1 1 0 1.191 0 NaN NaN 0
0 80.84 1 1 0 1.191 0 NaN NaN 0
0 80.77 1 1 0 1.191 0 NaN NaN 0
0 81.79 1 1 0 1.191 0 NaN NaN 0
0 81.02 1 1 0 1.191 0 NaN NaN 0
0 84.52 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 87.15 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 87.42 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 87.39 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 87.46 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 87.6 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 91.95 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 94.39 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 94.65 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 94.64 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 94.68 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 94.74 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 91.96 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 94.45 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 94.7 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 94.7 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 95.77 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 94.79 0.5051 0.9396 9.633 0.1663 0 NaN NaN 0
0 148.4 1 1 0 1.191 0 NaN NaN 0
0 153.7 1 1 0 1.191 0 NaN NaN 0
0 152.3 1 1 0 1.191 0 NaN NaN 0
0 154.4 1 1 0 1.191 0 NaN NaN 0
0 152.7 1 1 0 1.191 0 NaN NaN 0
0 152.3 1 1 0 1.191 0 NaN NaN 0
0 158.8 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 163.8 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 166.3 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 164.1 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 163.9 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 163.8 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 173.1 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 178.3 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 178.3 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 178.1 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 178.4 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 178.1 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 173.8 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 178.9 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 179.2 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 178.7 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 179.1 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
0 179 0.5908 0.9453 11.2 0.06309 0 NaN NaN 0
EOD
set output 'spring-0.1.png'
set multiplot layout 2,3 title 'spring-0.1: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $spring_0_1_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_1_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_1_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_1_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_1_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_1_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_1_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_1_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $spring_0_1_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_1_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_1_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_1_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_1_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_1_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_1_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_1_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $spring_0_1_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_1_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_1_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_1_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_1_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_1_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_1_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_1_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $spring_0_1_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_1_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_1_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_1_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_1_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_1_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_1_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_1_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$spring_0_25_substeps << EOD
1 31.43 0.1082 0.6185 5.832 0.4001 0 NaN NaN 1
2 54.65 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
4 98.53 0.2179 0.7383 11 0.278 0 NaN NaN 0
8 186 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
EOD
$spring_0_25_velocity_iterations << EOD
1 27.04 1 1 0 1.099 0 NaN NaN 0
2 28.87 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
4 31.22 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
10 31.43 0.1082 0.6185 5.832 0.4001 0 NaN NaN 1
EOD
$spring_0_25_position_iterations << EOD
0 30.45 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
1 31 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
2 31.43 0.1082 0.6185 5.832 0.4001 0 NaN NaN 1
4 31.23 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
10 31.28 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
30 31.2 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
EOD
$spring_0_25_default << EOD
0 31.43 0.1082 0.6185 5.832 0.4001 0 NaN NaN 1
EOD
$spring_0_25_grid << EOD
0 26.34 1 1 0 1.099 0 NaN NaN 0
0 27.07 1 1 0 1.099 0 NaN NaN 0
0 27.04 1 1 0 1.099 0 NaN NaN 0
0 27.03 1 1 0 1.099 0 NaN NaN 0
0 41.57 1 1 0 1.099 0 NaN NaN 0
0 39.02 1 1 0 1.099 0 NaN NaN 0
0 28.06 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 28.65 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 28.87 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 28.83 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 28.89 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 28.9 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 30.23 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 30.81 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 31.22 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 31.17 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 31.13 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 31.15 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 30.45 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 31 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 31.43 0.1082 0.6185 5.832 0.4001 0 NaN NaN 1
0 31.23 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 31.28 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 31.2 0.1082 0.6185 5.832 0.4001 0 NaN NaN 0
0 43.65 1 1 0 1.099 0 NaN NaN 0
0 44.85 1 1 0 1.099 0 NaN NaN 0
0 45.67 1 1 0 1.099 0 NaN NaN 0
0 45.8 1 1 0 1.099 0 NaN NaN 0
0 45.7 1 1 0 1.099 0 NaN NaN 0
0 45.5 1 1 0 1.099 0 NaN NaN 0
0 47.34 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 48.2 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 48.33 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 48.28 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 48.31 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 48.34 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 51.65 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 52.61 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 52.86 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 52.8 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 52.67 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 52.73 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 53.45 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 54.43 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 54.65 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 54.65 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 54.66 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 54.64 0.1489 0.6349 7.885 0.3567 0 NaN NaN 0
0 77.76 1 1 0 1.099 0 NaN NaN 0
0 80.97 1 1 0 1.099 0 NaN NaN 0
0 81.79 1 1 0 1.099 0 NaN NaN 0
0 81.69 1 1 0 1.099 0 NaN NaN 0
0 81.95 1 1 0 1.099 0 NaN NaN 0
0 82.35 1 1 0 1.099 0 NaN NaN 0
0 124.9 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 87.95 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 88.39 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 88.22 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 88.23 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 121.2 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 94.16 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 96.71 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 96.06 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 96.18 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 96.18 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 96.16 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 95.93 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 98.47 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 98.53 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 98.66 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 98.72 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 98.66 0.2179 0.7383 11 0.278 0 NaN NaN 0
0 150.9 1 1 0 1.099 0 NaN NaN 0
0 151.6 1 1 0 1.099 0 NaN NaN 0
0 165.3 1 1 0 1.099 0 NaN NaN 0
0 153.9 1 1 0 1.099 0 NaN NaN 0
0 173.2 1 1 0 1.099 0 NaN NaN 0
0 155.7 1 1 0 1.099 0 NaN NaN 0
0 169 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 167.5 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 177 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 165.6 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 165.5 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 165.4 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 175.8 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 180.3 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 180.2 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 184 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 181.3 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 181.3 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 180.8 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 186.2 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 186 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 182.7 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 182.7 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
0 182.5 0.3156 0.8577 15.43 0.1514 0 NaN NaN 0
EOD
set output 'spring-0.25.png'
set multiplot layout 2,3 title 'spring-0.25: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $spring_0_25_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_25_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_25_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_25_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_25_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_25_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_25_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_25_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $spring_0_25_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_25_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_25_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_25_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_25_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_25_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_25_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_25_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $spring_0_25_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_25_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_25_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_25_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_25_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_25_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_25_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_25_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $spring_0_25_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_25_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_25_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_25_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_25_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_25_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_25_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_25_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$spring_0_5_substeps << EOD
1 32.94 0.0457 0.2884 6.438 0.216 0 NaN NaN 1
2 53.67 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
4 102 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
8 188.7 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
EOD
$spring_0_5_velocity_iterations << EOD
1 27.42 1 1 0 1.03 0 NaN NaN 0
2 28.92 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
4 31.87 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
10 32.94 0.0457 0.2884 6.438 0.216 0 NaN NaN 1
EOD
$spring_0_5_position_iterations << EOD
0 32.15 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
1 32.78 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
2 32.94 0.0457 0.2884 6.438 0.216 0 NaN NaN 1
4 33.01 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
10 32.92 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
30 33.01 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
EOD
$spring_0_5_default << EOD
0 32.94 0.0457 0.2884 6.438 0.216 0 NaN NaN 1
EOD
$spring_0_5_grid << EOD
0 26.34 1 1 0 1.03 0 NaN NaN 0
0 27.1 1 1 0 1.03 0 NaN NaN 0
0 27.42 1 1 0 1.03 0 NaN NaN 0
0 27.06 1 1 0 1.03 0 NaN NaN 0
0 27.17 1 1 0 1.03 0 NaN NaN 0
0 26.97 1 1 0 1.03 0 NaN NaN 0
0 28.04 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 28.61 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 28.92 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 28.92 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 28.85 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 28.88 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 30.95 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 31.58 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 31.87 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 31.85 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 31.85 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 31.98 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 32.15 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 32.78 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 32.94 0.0457 0.2884 6.438 0.216 0 NaN NaN 1
0 33.01 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 32.92 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 33.01 0.0457 0.2884 6.438 0.216 0 NaN NaN 0
0 43.76 1 1 0 1.03 0 NaN NaN 0
0 45.5 1 1 0 1.03 0 NaN NaN 0
0 44.79 1 1 0 1.03 0 NaN NaN 0
0 45.66 1 1 0 1.03 0 NaN NaN 0
0 45.62 1 1 0 1.03 0 NaN NaN 0
0 45.63 1 1 0 1.03 0 NaN NaN 0
0 47.43 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 48.3 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 48.93 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 48.85 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 48.81 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 48.87 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 57.81 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 52.78 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 52.97 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 52.88 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 80.01 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 77.76 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 52.32 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 71.73 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 53.67 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 53.6 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 53.68 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 53.72 0.05426 0.3396 8.097 0.1937 0 NaN NaN 0
0 79.21 1 1 0 1.03 0 NaN NaN 0
0 81.36 1 1 0 1.03 0 NaN NaN 0
0 80.82 1 1 0 1.03 0 NaN NaN 0
0 81.3 1 1 0 1.03 0 NaN NaN 0
0 81.68 1 1 0 1.03 0 NaN NaN 0
0 80.76 1 1 0 1.03 0 NaN NaN 0
0 84.46 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 87.36 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 87.48 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 87.55 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 87.5 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 88.44 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 94.49 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 142 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 144 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 97.39 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 97.45 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 97.33 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 98.48 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 106.6 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 102 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 139.7 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 101.4 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 101.2 0.08808 0.5573 11.05 0.1567 0 NaN NaN 0
0 149.2 1 1 0 1.03 0 NaN NaN 0
0 154.3 1 1 0 1.03 0 NaN NaN 0
0 155.6 1 1 0 1.03 0 NaN NaN 0
0 156.9 1 1 0 1.03 0 NaN NaN 0
0 154.2 1 1 0 1.03 0 NaN NaN 0
0 156.6 1 1 0 1.03 0 NaN NaN 0
0 159.2 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 166.7 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 168.7 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 170.5 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 218.4 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 166.3 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 179.8 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 185.5 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 185.6 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 185.6 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 183.5 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 183.4 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 183.3 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 191.8 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 188.7 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 188.4 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 188.6 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
0 189.3 0.1416 0.7383 15.52 0.09512 0 NaN NaN 0
EOD
set output 'spring-0.5.png'
set multiplot layout 2,3 title 'spring-0.5: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $spring_0_5_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_5_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_5_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_5_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_5_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_5_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_5_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_5_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $spring_0_5_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_5_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_5_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_5_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_5_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_5_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_5_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_5_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $spring_0_5_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_5_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_5_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_5_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_5_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_5_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_5_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_5_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $spring_0_5_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_0_5_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_0_5_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_0_5_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_0_5_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_0_5_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_0_5_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_0_5_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$spring_1_0_substeps << EOD
1 36.12 0.0156 0.092 7.166 0.1529 0 NaN NaN 1
2 63.72 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
4 105.2 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
8 191.7 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
EOD
$spring_1_0_velocity_iterations << EOD
1 27.44 1 1 0 1.017 0 NaN NaN 0
2 29.37 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
4 32.87 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
10 36.12 0.0156 0.092 7.166 0.1529 0 NaN NaN 1
EOD
$spring_1_0_position_iterations << EOD
0 35.4 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
1 36.14 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
2 36.12 0.0156 0.092 7.166 0.1529 0 NaN NaN 1
4 36.19 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
10 36.12 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
30 36.29 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
EOD
$spring_1_0_default << EOD
0 36.12 0.0156 0.092 7.166 0.1529 0 NaN NaN 1
EOD
$spring_1_0_grid << EOD
0 26.5 1 1 0 1.017 0 NaN NaN 0
0 27.36 1 1 0 1.017 0 NaN NaN 0
0 27.44 1 1 0 1.017 0 NaN NaN 0
0 27.05 1 1 0 1.017 0 NaN NaN 0
0 27.08 1 1 0 1.017 0 NaN NaN 0
0 27.04 1 1 0 1.017 0 NaN NaN 0
0 28.46 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 29 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 29.37 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 29.27 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 29.46 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 29.25 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 31.72 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 32.48 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 32.87 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 32.78 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 32.57 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 32.6 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 35.4 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 36.14 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 36.12 0.0156 0.092 7.166 0.1529 0 NaN NaN 1
0 36.19 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 36.12 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 36.29 0.0156 0.092 7.166 0.1529 0 NaN NaN 0
0 43.63 1 1 0 1.017 0 NaN NaN 0
0 45.19 1 1 0 1.017 0 NaN NaN 0
0 44.93 1 1 0 1.017 0 NaN NaN 0
0 44.93 1 1 0 1.017 0 NaN NaN 0
0 44.81 1 1 0 1.017 0 NaN NaN 0
0 44.82 1 1 0 1.017 0 NaN NaN 0
0 48.4 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 49.53 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 49.26 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 49.25 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 49.18 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 49.28 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 54.14 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 55.29 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 55.36 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 55.38 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 55.35 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 55.37 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 62.59 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 63.88 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 63.72 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 63.92 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 63.96 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 63.94 0.01746 0.1221 6.549 0.1356 0 NaN NaN 0
0 77.88 1 1 0 1.017 0 NaN NaN 0
0 80.97 1 1 0 1.017 0 NaN NaN 0
0 81.78 1 1 0 1.017 0 NaN NaN 0
0 82.73 1 1 0 1.017 0 NaN NaN 0
0 83.61 1 1 0 1.017 0 NaN NaN 0
0 83.23 1 1 0 1.017 0 NaN NaN 0
0 87.45 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 90.21 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 90.44 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 128.9 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 89.35 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 89.27 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 97.81 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 100.3 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 99.65 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 99.67 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 100.6 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 99.79 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 102.3 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 105.3 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 105.2 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 105 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 105.1 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 156.5 0.0452 0.3396 5.378 0.1095 0 NaN NaN 0
0 147.4 1 1 0 1.017 0 NaN NaN 0
0 150.9 1 1 0 1.017 0 NaN NaN 0
0 152.2 1 1 0 1.017 0 NaN NaN 0
0 154.9 1 1 0 1.017 0 NaN NaN 0
0 164.6 1 1 0 1.017 0 NaN NaN 0
0 152.7 1 1 0 1.017 0 NaN NaN 0
0 158.9 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 163.9 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 163.9 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 165.3 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 168.1 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 163.7 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 178.7 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 184.2 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 184 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 190.8 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 184 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 185.3 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 187.1 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 193.2 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 191.7 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 194.7 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 191.8 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
0 193.5 0.08545 0.5573 3.999 0.06673 0 NaN NaN 0
EOD
set output 'spring-1.0.png'
set multiplot layout 2,3 title 'spring-1.0: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $spring_1_0_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_1_0_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_1_0_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_1_0_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_1_0_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_1_0_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_1_0_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_1_0_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $spring_1_0_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_1_0_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_1_0_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_1_0_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_1_0_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_1_0_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_1_0_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_1_0_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $spring_1_0_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_1_0_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_1_0_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_1_0_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_1_0_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_1_0_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_1_0_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_1_0_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $spring_1_0_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spring_1_0_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spring_1_0_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spring_1_0_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spring_1_0_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spring_1_0_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spring_1_0_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spring_1_0_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_cone_substeps << EOD
1 99.34 0.345 1.904 0 0 0.345 0 NaN 1
2 180.7 0.1975 1.308 0 0 0.1975 0 NaN 0
4 345 0.08914 0.6489 0 0 0.08914 0 NaN 0
8 677.3 0.0283 0.216 0 0 0.0283 0 NaN 0
EOD
$singular_cone_velocity_iterations << EOD
1 66.6 0.345 1.904 0 0 0.345 0 NaN 0
2 71.38 0.345 1.904 0 0 0.345 0 NaN 0
4 78.22 0.345 1.904 0 0 0.345 0 NaN 0
10 99.34 0.345 1.904 0 0 0.345 0 NaN 1
EOD
$singular_cone_position_iterations << EOD
0 73.06 2.642 2.642 0 0 2.642 0 NaN 0
1 86.12 0.5366 2.266 0 0 0.5366 0 NaN 0
2 99.34 0.345 1.904 0 0 0.345 0 NaN 1
4 119.1 0.1975 1.308 0 0 0.1975 0 NaN 0
10 179.4 0.06446 0.4783 0 0 0.06446 0 NaN 0
30 379.1 0.005853 0.04529 0 0 0.005851 0 NaN 0
EOD
$singular_cone_default << EOD
0 99.34 0.345 1.904 0 0 0.345 0 NaN 1
EOD
$singular_cone_grid << EOD
0 40.05 2.642 2.642 0 0 2.642 0 NaN 0
0 53.37 0.5366 2.266 0 0 0.5366 0 NaN 0
0 66.6 0.345 1.904 0 0 0.345 0 NaN 0
0 86.57 0.1975 1.308 0 0 0.1975 0 NaN 0
0 146.7 0.06446 0.4783 0 0 0.06446 0 NaN 0
0 345.7 0.005853 0.04529 0 0 0.005851 0 NaN 0
0 45.2 2.642 2.642 0 0 2.642 0 NaN 0
0 58.33 0.5366 2.266 0 0 0.5366 0 NaN 0
0 71.38 0.345 1.904 0 0 0.345 0 NaN 0
0 91.17 0.1975 1.308 0 0 0.1975 0 NaN 0
0 151.4 0.06446 0.4783 0 0 0.06446 0 NaN 0
0 353 0.005853 0.04529 0 0 0.005851 0 NaN 0
0 51.4 2.642 2.642 0 0 2.642 0 NaN 0
0 64.88 0.5366 2.266 0 0 0.5366 0 NaN 0
0 78.22 0.345 1.904 0 0 0.345 0 NaN 0
0 97.95 0.1975 1.308 0 0 0.1975 0 NaN 0
0 158.2 0.06446 0.4783 0 0 0.06446 0 NaN 0
0 360.1 0.005853 0.04529 0 0 0.005851 0 NaN 0
0 73.06 2.642 2.642 0 0 2.642 0 NaN 0
0 86.12 0.5366 2.266 0 0 0.5366 0 NaN 0
0 99.34 0.345 1.904 0 0 0.345 0 NaN 1
0 119.1 0.1975 1.308 0 0 0.1975 0 NaN 0
0 179.4 0.06446 0.4783 0 0 0.06446 0 NaN 0
0 379.1 0.005853 0.04529 0 0 0.005851 0 NaN 0
0 68.26 2.642 2.642 0 0 2.642 0 NaN 0
0 95.02 0.345 1.904 0 0 0.345 0 NaN 0
0 114.8 0.1975 1.308 0 0 0.1975 0 NaN 0
0 155.9 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 297.3 0.01752 0.1347 0 0 0.01752 0 NaN 0
0 681 0.0002725 0.002109 0 0 0.000271 0 NaN 0
0 78.71 2.642 2.642 0 0 2.642 0 NaN 0
0 105.4 0.345 1.904 0 0 0.345 0 NaN 0
0 126.3 0.1975 1.308 0 0 0.1975 0 NaN 0
0 165.7 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 286.8 0.01752 0.1347 0 0 0.01752 0 NaN 0
0 701.9 0.0002725 0.002109 0 0 0.000271 0 NaN 0
0 92.37 2.642 2.642 0 0 2.642 0 NaN 0
0 118.2 0.345 1.904 0 0 0.345 0 NaN 0
0 139.1 0.1975 1.308 0 0 0.1975 0 NaN 0
0 181.2 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 299.6 0.01752 0.1347 0 0 0.01752 0 NaN 0
0 706.4 0.0002725 0.002109 0 0 0.000271 0 NaN 0
0 133.9 2.642 2.642 0 0 2.642 0 NaN 0
0 160.6 0.345 1.904 0 0 0.345 0 NaN 0
0 180.7 0.1975 1.308 0 0 0.1975 0 NaN 0
0 225.7 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 345.9 0.01752 0.1347 0 0 0.01752 0 NaN 0
0 1069 0.0002725 0.002109 0 0 0.000271 0 NaN 0
0 125.3 2.642 2.642 0 0 2.642 0 NaN 0
0 171.7 0.1975 1.308 0 0 0.1975 0 NaN 0
0 211 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 292.7 0.0283 0.216 0 0 0.0283 0 NaN 0
0 539.1 0.002074 0.01606 0 0 0.002072 0 NaN 0
0 1339 1.005e-05 1.005e-05 0 0 9.167e-10 0 NaN 0
0 145.2 2.642 2.642 0 0 2.642 0 NaN 0
0 193 0.1975 1.308 0 0 0.1975 0 NaN 0
0 234.1 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 313.9 0.0283 0.216 0 0 0.0283 0 NaN 0
0 557.1 0.002074 0.01606 0 0 0.002072 0 NaN 0
0 1384 1.005e-05 1.005e-05 0 0 9.167e-10 0 NaN 0
0 169.9 2.642 2.642 0 0 2.642 0 NaN 0
0 224.3 0.1975 1.308 0 0 0.1975 0 NaN 0
0 385.6 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 343.9 0.0283 0.216 0 0 0.0283 0 NaN 0
0 590.5 0.002074 0.01606 0 0 0.002072 0 NaN 0
0 1403 1.005e-05 1.005e-05 0 0 9.167e-10 0 NaN 0
0 255.5 2.642 2.642 0 0 2.642 0 NaN 0
0 304.3 0.1975 1.308 0 0 0.1975 0 NaN 0
0 345 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 428.6 0.0283 0.216 0 0 0.0283 0 NaN 0
0 670.2 0.002074 0.01606 0 0 0.002072 0 NaN 0
0 1479 1.005e-05 1.005e-05 0 0 9.167e-10 0 NaN 0
0 239.7 2.642 2.642 0 0 2.642 0 NaN 0
0 322.9 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 404.1 0.0283 0.216 0 0 0.0283 0 NaN 0
0 569.2 0.004743 0.03671 0 0 0.004742 0 NaN 0
0 1065 3.754e-05 0.0002804 0 0 3.49e-05 0 NaN 0
0 2709 1.005e-05 1.005e-05 0 0 9.167e-10 0 NaN 0
0 278.7 2.642 2.642 0 0 2.642 0 NaN 0
0 371.9 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 447.2 0.0283 0.216 0 0 0.0283 0 NaN 0
0 611.3 0.004743 0.03671 0 0 0.004742 0 NaN 0
0 1106 3.754e-05 0.0002804 0 0 3.49e-05 0 NaN 0
0 2736 1.005e-05 1.005e-05 0 0 9.167e-10 0 NaN 0
0 331.6 2.642 2.642 0 0 2.642 0 NaN 0
0 421.9 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 510.1 0.0283 0.216 0 0 0.0283 0 NaN 0
0 671.2 0.004743 0.03671 0 0 0.004742 0 NaN 0
0 1221 3.754e-05 0.0002804 0 0 3.49e-05 0 NaN 0
0 3057 1.005e-05 1.005e-05 0 0 9.167e-10 0 NaN 0
0 500.4 2.642 2.642 0 0 2.642 0 NaN 0
0 595.5 0.08914 0.6489 0 0 0.08914 0 NaN 0
0 677.3 0.0283 0.216 0 0 0.0283 0 NaN 0
0 832.8 0.004743 0.03671 0 0 0.004742 0 NaN 0
0 1330 3.754e-05 0.0002804 0 0 3.49e-05 0 NaN 0
0 2942 1.005e-05 1.005e-05 0 0 9.167e-10 0 NaN 0
EOD
set output 'singular-cone.png'
set multiplot layout 1,3 title 'singular-cone: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $singular_cone_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_cone_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_cone_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_cone_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_cone_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_cone_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_cone_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_cone_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $singular_cone_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_cone_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_cone_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_cone_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_cone_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_cone_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_cone_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_cone_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $singular_cone_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $singular_cone_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $singular_cone_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $singular_cone_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $singular_cone_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $singular_cone_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $singular_cone_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $singular_cone_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
