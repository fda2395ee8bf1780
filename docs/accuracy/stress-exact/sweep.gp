# Error against ns per world-step, one curve per knob: written by
# ./build/tools/manyworlds sweep --scenes spin-unstable,flywheel,singular-hinge-90,singular-hinge-180,singular-fixed-90,singular-fixed-180,singular-slider-90,singular-rackpinion,singular-swingtwist,dt-1/15,dt-1e-4,mass-range,mass-range-hanging,far-1e4,chain16-r1000,chain64 --worlds 256 --passes 2 --solver exact --out docs/accuracy/stress-exact --overwrite
# Run: gnuplot sweep.gp (in this directory).
set terminal pngcairo noenhanced size 1500,900 font ',10'
set logscale xy
set grid
set format y '%.0e'
set key below horizontal
set xlabel 'ns per world-step (256 worlds, 1 thread(s), AVX3)'
$spin_unstable_substeps << EOD
1 8.593 0 0 0 0 2.727e-06 4.597e-08 NaN 1
2 15.56 0 0 0 0 8.518e-07 9.265e-08 NaN 0
4 29.15 0 0 0 0 6.444e-07 1.714e-07 NaN 0
EOD
$spin_unstable_velocity_iterations << EOD
10 8.593 0 0 0 0 2.727e-06 4.597e-08 NaN 1
EOD
$spin_unstable_position_iterations << EOD
2 8.593 0 0 0 0 2.727e-06 4.597e-08 NaN 1
4 8.562 0 0 0 0 2.727e-06 4.597e-08 NaN 0
10 8.589 0 0 0 0 2.727e-06 4.597e-08 NaN 0
30 8.589 0 0 0 0 2.727e-06 4.597e-08 NaN 0
EOD
$spin_unstable_default << EOD
0 8.593 0 0 0 0 2.727e-06 4.597e-08 NaN 1
EOD
$spin_unstable_grid << EOD
0 8.593 0 0 0 0 2.727e-06 4.597e-08 NaN 1
0 8.562 0 0 0 0 2.727e-06 4.597e-08 NaN 0
0 8.589 0 0 0 0 2.727e-06 4.597e-08 NaN 0
0 8.589 0 0 0 0 2.727e-06 4.597e-08 NaN 0
0 15.56 0 0 0 0 8.518e-07 9.265e-08 NaN 0
0 15.36 0 0 0 0 8.518e-07 9.265e-08 NaN 0
0 15.36 0 0 0 0 8.518e-07 9.265e-08 NaN 0
0 15.38 0 0 0 0 8.518e-07 9.265e-08 NaN 0
0 29.15 0 0 0 0 6.444e-07 1.714e-07 NaN 0
0 29.27 0 0 0 0 6.444e-07 1.714e-07 NaN 0
0 29.64 0 0 0 0 6.444e-07 1.714e-07 NaN 0
0 29.19 0 0 0 0 6.444e-07 1.714e-07 NaN 0
EOD
set output 'spin-unstable.png'
set multiplot layout 1,3 title 'spin-unstable: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'trajectory error RMS (rad)'
plot $spin_unstable_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spin_unstable_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spin_unstable_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spin_unstable_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spin_unstable_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spin_unstable_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spin_unstable_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spin_unstable_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $spin_unstable_grid using 2:8 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $spin_unstable_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $spin_unstable_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $spin_unstable_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $spin_unstable_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $spin_unstable_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $spin_unstable_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $spin_unstable_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$flywheel_substeps << EOD
1 35.13 0 0 2.436e-09 0 1.151e-06 0 NaN 1
2 67.17 0 0 1.218e-09 0 1.563e-06 0 NaN 0
4 132.8 0 0 6.091e-10 0 1.719e-06 0 NaN 0
EOD
$flywheel_velocity_iterations << EOD
10 35.13 0 0 2.436e-09 0 1.151e-06 0 NaN 1
EOD
$flywheel_position_iterations << EOD
2 35.13 0 0 2.436e-09 0 1.151e-06 0 NaN 1
4 35.44 0 0 2.436e-09 0 1.151e-06 0 NaN 0
10 34.87 0 0 2.436e-09 0 1.151e-06 0 NaN 0
30 35.52 0 0 2.436e-09 0 1.151e-06 0 NaN 0
EOD
$flywheel_default << EOD
0 35.13 0 0 2.436e-09 0 1.151e-06 0 NaN 1
EOD
$flywheel_grid << EOD
0 35.13 0 0 2.436e-09 0 1.151e-06 0 NaN 1
0 35.44 0 0 2.436e-09 0 1.151e-06 0 NaN 0
0 34.87 0 0 2.436e-09 0 1.151e-06 0 NaN 0
0 35.52 0 0 2.436e-09 0 1.151e-06 0 NaN 0
0 67.17 0 0 1.218e-09 0 1.563e-06 0 NaN 0
0 67.27 0 0 1.218e-09 0 1.563e-06 0 NaN 0
0 67.84 0 0 1.218e-09 0 1.563e-06 0 NaN 0
0 66.78 0 0 1.218e-09 0 1.563e-06 0 NaN 0
0 132.8 0 0 6.091e-10 0 1.719e-06 0 NaN 0
0 131.8 0 0 6.091e-10 0 1.719e-06 0 NaN 0
0 132.7 0 0 6.091e-10 0 1.719e-06 0 NaN 0
0 134.9 0 0 6.091e-10 0 1.719e-06 0 NaN 0
EOD
set output 'flywheel.png'
set multiplot layout 1,3 title 'flywheel: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $flywheel_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $flywheel_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $flywheel_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $flywheel_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $flywheel_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $flywheel_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $flywheel_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $flywheel_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $flywheel_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $flywheel_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $flywheel_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $flywheel_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $flywheel_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $flywheel_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $flywheel_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $flywheel_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$singular_hinge_90_substeps << EOD
1 103.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
2 202.4 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
4 417.9 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
EOD
$singular_hinge_90_velocity_iterations << EOD
10 103.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_hinge_90_position_iterations << EOD
2 103.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
4 134.9 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
10 230.2 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
30 539.3 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
EOD
$singular_hinge_90_default << EOD
0 103.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_hinge_90_grid << EOD
0 103.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
0 134.9 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 230.2 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 539.3 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 202.4 1.53e-05 0.0001185 0 0 1.636e-05 0 NaN 0
0 270.2 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 459.4 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 1099 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 417.9 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 531.8 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 929.1 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
0 2158 7.276e-12 7.276e-12 0 0 4.132e-06 0 NaN 0
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
1 106 0.3138 2.142 0 0 0.3138 0 NaN 1
2 208.8 0.1474 1.142 0 0 0.1474 0 NaN 0
4 418.9 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
EOD
$singular_hinge_180_velocity_iterations << EOD
10 106 0.3138 2.142 0 0 0.3138 0 NaN 1
EOD
$singular_hinge_180_position_iterations << EOD
2 106 0.3138 2.142 0 0 0.3138 0 NaN 1
4 137 0.1474 1.142 0 0 0.1474 0 NaN 0
10 230.3 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
30 553 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
EOD
$singular_hinge_180_default << EOD
0 106 0.3138 2.142 0 0 0.3138 0 NaN 1
EOD
$singular_hinge_180_grid << EOD
0 106 0.3138 2.142 0 0 0.3138 0 NaN 1
0 137 0.1474 1.142 0 0 0.1474 0 NaN 0
0 230.3 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 553 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 208.8 0.1474 1.142 0 0 0.1474 0 NaN 0
0 276.1 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 456.9 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 1089 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 418.9 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 544.3 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 925.2 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
0 2126 3.465e-10 3.465e-10 0 0 4.325e-06 0 NaN 0
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
1 29.18 0.07369 0.5708 0 0 0.07369 0 NaN 1
2 57.67 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
4 106.8 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
EOD
$singular_fixed_90_velocity_iterations << EOD
10 29.18 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_fixed_90_position_iterations << EOD
2 29.18 0.07369 0.5708 0 0 0.07369 0 NaN 1
4 29.65 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
10 30.6 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
30 31.12 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
EOD
$singular_fixed_90_default << EOD
0 29.18 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_fixed_90_grid << EOD
0 29.18 0.07369 0.5708 0 0 0.07369 0 NaN 1
0 29.65 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 30.6 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 31.12 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 57.67 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 57.59 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 55.4 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 55.13 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 106.8 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 107.2 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 108.2 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 105.1 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
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
1 30.58 0.3138 2.142 0 0 0.3138 0 NaN 1
2 55.73 0.1474 1.142 0 0 0.1474 0 NaN 0
4 111.7 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
EOD
$singular_fixed_180_velocity_iterations << EOD
10 30.58 0.3138 2.142 0 0 0.3138 0 NaN 1
EOD
$singular_fixed_180_position_iterations << EOD
2 30.58 0.3138 2.142 0 0 0.3138 0 NaN 1
4 31.24 0.1474 1.142 0 0 0.1474 0 NaN 0
10 30.03 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
30 30.61 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
EOD
$singular_fixed_180_default << EOD
0 30.58 0.3138 2.142 0 0 0.3138 0 NaN 1
EOD
$singular_fixed_180_grid << EOD
0 30.58 0.3138 2.142 0 0 0.3138 0 NaN 1
0 31.24 0.1474 1.142 0 0 0.1474 0 NaN 0
0 30.03 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 30.61 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 55.73 0.1474 1.142 0 0 0.1474 0 NaN 0
0 57.65 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 57.83 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 57.34 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 111.7 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 110.2 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 110.9 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
0 111.4 7.276e-12 7.276e-12 0 0 4.274e-06 0 NaN 0
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
1 111.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
2 218 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
4 437.6 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
EOD
$singular_slider_90_velocity_iterations << EOD
10 111.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_slider_90_position_iterations << EOD
2 111.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
4 131.3 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
10 202.4 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
30 504.6 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
EOD
$singular_slider_90_default << EOD
0 111.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
EOD
$singular_slider_90_grid << EOD
0 111.8 0.07369 0.5708 0 0 0.07369 0 NaN 1
0 131.3 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 202.4 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 504.6 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 218 1.908e-06 1.478e-05 0 0 4.247e-06 0 NaN 0
0 275.5 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 454.3 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 1018 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 437.6 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 554.9 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 886.6 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
0 2070 9.095e-13 9.095e-13 0 0 4.049e-06 0 NaN 0
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
1 216.8 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 1
2 434.1 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
4 856.9 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
EOD
$singular_rackpinion_velocity_iterations << EOD
10 216.8 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 1
EOD
$singular_rackpinion_position_iterations << EOD
2 216.8 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 1
4 224.2 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
10 218.6 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
30 216.1 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
EOD
$singular_rackpinion_default << EOD
0 216.8 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 1
EOD
$singular_rackpinion_grid << EOD
0 216.8 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 1
0 224.2 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
0 218.6 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
0 216.1 3.958e-07 1.342e-06 2.913e-08 0.0008918 0.008918 NaN 6.855e-07 0
0 434.1 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
0 430.7 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
0 415.9 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
0 415.5 2.943e-07 1.157e-06 3.75e-08 0.000835 0.008351 NaN 5.097e-07 0
0 856.9 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
0 872.4 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
0 846.8 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
0 851.3 5.875e-07 2.117e-06 3.42e-08 0.0003272 0.003273 NaN 1.018e-06 0
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
1 83.48 0.3282 1.893 0 0 0.3282 0 NaN 1
2 157.7 0.1833 1.286 0 0 0.1833 0 NaN 0
4 318 0.07181 0.5482 0 0 0.0718 0 NaN 0
EOD
$singular_swingtwist_velocity_iterations << EOD
10 83.48 0.3282 1.893 0 0 0.3282 0 NaN 1
EOD
$singular_swingtwist_position_iterations << EOD
2 83.48 0.3282 1.893 0 0 0.3282 0 NaN 1
4 102.3 0.1833 1.286 0 0 0.1833 0 NaN 0
10 172.3 0.04579 0.3526 0 0 0.04579 0 NaN 0
30 411.2 0.0005268 0.00408 0 0 0.0005263 0 NaN 0
EOD
$singular_swingtwist_default << EOD
0 83.48 0.3282 1.893 0 0 0.3282 0 NaN 1
EOD
$singular_swingtwist_grid << EOD
0 83.48 0.3282 1.893 0 0 0.3282 0 NaN 1
0 102.3 0.1833 1.286 0 0 0.1833 0 NaN 0
0 172.3 0.04579 0.3526 0 0 0.04579 0 NaN 0
0 411.2 0.0005268 0.00408 0 0 0.0005263 0 NaN 0
0 157.7 0.1833 1.286 0 0 0.1833 0 NaN 0
0 202.8 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 347.9 0.004906 0.038 0 0 0.004906 0 NaN 0
0 844.7 4.065e-06 5.058e-06 0 0 1.327e-07 0 NaN 0
0 318 0.07181 0.5482 0 0 0.0718 0 NaN 0
0 411.1 0.01198 0.09275 0 0 0.01198 0 NaN 0
0 676.5 5.67e-05 0.0004381 0 0 5.604e-05 0 NaN 0
0 1678 4.046e-06 4.046e-06 0 0 1.193e-08 0 NaN 0
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
1 655.3 0.0009973 0.007797 0.09712 0.2014 0.1558 49.42 NaN 1
2 1179 1.484e-06 9.118e-06 0.06238 0.09817 0.102 26.62 NaN 0
4 1998 1.085e-06 8.027e-06 0.03734 0.04492 0.05966 14.49 NaN 0
EOD
$dt_1_15_velocity_iterations << EOD
10 655.3 0.0009973 0.007797 0.09712 0.2014 0.1558 49.42 NaN 1
EOD
$dt_1_15_position_iterations << EOD
2 655.3 0.0009973 0.007797 0.09712 0.2014 0.1558 49.42 NaN 1
4 850.4 2.423e-06 2.23e-05 0.09721 0.2033 0.1585 47.4 NaN 0
10 885.5 5.934e-07 5.37e-06 0.09721 0.2033 0.1585 47.39 NaN 0
30 826 5.934e-07 5.37e-06 0.09721 0.2033 0.1585 47.39 NaN 0
EOD
$dt_1_15_default << EOD
0 655.3 0.0009973 0.007797 0.09712 0.2014 0.1558 49.42 NaN 1
EOD
$dt_1_15_grid << EOD
0 655.3 0.0009973 0.007797 0.09712 0.2014 0.1558 49.42 NaN 1
0 850.4 2.423e-06 2.23e-05 0.09721 0.2033 0.1585 47.4 NaN 0
0 885.5 5.934e-07 5.37e-06 0.09721 0.2033 0.1585 47.39 NaN 0
0 826 5.934e-07 5.37e-06 0.09721 0.2033 0.1585 47.39 NaN 0
0 1179 1.484e-06 9.118e-06 0.06238 0.09817 0.102 26.62 NaN 0
0 1202 1.484e-06 9.118e-06 0.06238 0.09817 0.102 26.62 NaN 0
0 1349 1.484e-06 9.118e-06 0.06238 0.09817 0.102 26.62 NaN 0
0 1353 1.484e-06 9.118e-06 0.06238 0.09817 0.102 26.62 NaN 0
0 1998 1.085e-06 8.027e-06 0.03734 0.04492 0.05966 14.49 NaN 0
0 2029 1.085e-06 8.027e-06 0.03734 0.04492 0.05966 14.49 NaN 0
0 2036 1.085e-06 8.027e-06 0.03734 0.04492 0.05966 14.49 NaN 0
0 1854 1.085e-06 8.027e-06 0.03734 0.04492 0.05966 14.49 NaN 0
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
1 350.7 2.165e-06 1.015e-05 0.0002592 0.001982 0.006933 0.1034 NaN 1
2 651.4 2.165e-06 1.004e-05 0.0001298 0.001908 0.006909 0.03652 NaN 0
4 1231 2.349e-06 1.002e-05 6.49e-05 0.002161 0.006646 0.2057 NaN 0
EOD
$dt_1e_4_velocity_iterations << EOD
10 350.7 2.165e-06 1.015e-05 0.0002592 0.001982 0.006933 0.1034 NaN 1
EOD
$dt_1e_4_position_iterations << EOD
2 350.7 2.165e-06 1.015e-05 0.0002592 0.001982 0.006933 0.1034 NaN 1
4 356.6 2.165e-06 1.015e-05 0.0002592 0.001982 0.006933 0.1034 NaN 0
10 349.2 2.165e-06 1.015e-05 0.0002592 0.001982 0.006933 0.1034 NaN 0
30 349.8 2.165e-06 1.015e-05 0.0002592 0.001982 0.006933 0.1034 NaN 0
EOD
$dt_1e_4_default << EOD
0 350.7 2.165e-06 1.015e-05 0.0002592 0.001982 0.006933 0.1034 NaN 1
EOD
$dt_1e_4_grid << EOD
0 350.7 2.165e-06 1.015e-05 0.0002592 0.001982 0.006933 0.1034 NaN 1
0 356.6 2.165e-06 1.015e-05 0.0002592 0.001982 0.006933 0.1034 NaN 0
0 349.2 2.165e-06 1.015e-05 0.0002592 0.001982 0.006933 0.1034 NaN 0
0 349.8 2.165e-06 1.015e-05 0.0002592 0.001982 0.006933 0.1034 NaN 0
0 651.4 2.165e-06 1.004e-05 0.0001298 0.001908 0.006909 0.03652 NaN 0
0 669 2.165e-06 1.004e-05 0.0001298 0.001908 0.006909 0.03652 NaN 0
0 653 2.165e-06 1.004e-05 0.0001298 0.001908 0.006909 0.03652 NaN 0
0 643.1 2.165e-06 1.004e-05 0.0001298 0.001908 0.006909 0.03652 NaN 0
0 1231 2.349e-06 1.002e-05 6.49e-05 0.002161 0.006646 0.2057 NaN 0
0 1155 2.349e-06 1.002e-05 6.49e-05 0.002161 0.006646 0.2057 NaN 0
0 1192 2.349e-06 1.002e-05 6.49e-05 0.002161 0.006646 0.2057 NaN 0
0 1216 2.349e-06 1.002e-05 6.49e-05 0.002161 0.006646 0.2057 NaN 0
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
1 349.1 0.0213 0.3077 5.623 2.38 1.9 1.042e+06 NaN 1
2 629.4 0.007705 0.1255 5.056 1.457 1.437 7.496e+05 NaN 0
4 1169 0.0005313 0.01035 4.463 1.036 1.269 5.308e+05 NaN 0
EOD
$mass_range_velocity_iterations << EOD
10 349.1 0.0213 0.3077 5.623 2.38 1.9 1.042e+06 NaN 1
EOD
$mass_range_position_iterations << EOD
2 349.1 0.0213 0.3077 5.623 2.38 1.9 1.042e+06 NaN 1
4 387.1 5.472e-06 0.0001271 5.278 2.279 1.844 1.042e+06 NaN 0
10 391.1 1.345e-06 9.69e-06 5.278 2.279 1.844 1.042e+06 NaN 0
30 390.8 1.345e-06 9.69e-06 5.278 2.279 1.844 1.042e+06 NaN 0
EOD
$mass_range_default << EOD
0 349.1 0.0213 0.3077 5.623 2.38 1.9 1.042e+06 NaN 1
EOD
$mass_range_grid << EOD
0 349.1 0.0213 0.3077 5.623 2.38 1.9 1.042e+06 NaN 1
0 387.1 5.472e-06 0.0001271 5.278 2.279 1.844 1.042e+06 NaN 0
0 391.1 1.345e-06 9.69e-06 5.278 2.279 1.844 1.042e+06 NaN 0
0 390.8 1.345e-06 9.69e-06 5.278 2.279 1.844 1.042e+06 NaN 0
0 629.4 0.007705 0.1255 5.056 1.457 1.437 7.496e+05 NaN 0
0 670.7 3.817e-06 8.941e-05 4.767 1.442 1.432 7.495e+05 NaN 0
0 684.5 1.061e-06 1.005e-05 4.767 1.442 1.432 7.495e+05 NaN 0
0 685.2 1.061e-06 1.005e-05 4.767 1.442 1.432 7.495e+05 NaN 0
0 1169 0.0005313 0.01035 4.463 1.036 1.269 5.308e+05 NaN 0
0 1222 9.681e-07 7.695e-06 4.43 1.037 1.27 5.308e+05 NaN 0
0 1227 9.681e-07 7.695e-06 4.43 1.037 1.27 5.308e+05 NaN 0
0 1234 9.681e-07 7.695e-06 4.43 1.037 1.27 5.308e+05 NaN 0
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
1 387.3 0.1941 1.158 1.845 0.5403 0.4824 1.804e+06 NaN 1
2 769.2 0.1821 1.119 3.407 0.4324 0.6081 2.106e+06 NaN 0
4 1499 0.255 1.424 7.737 0.7884 1.512 3.521e+06 NaN 0
EOD
$mass_range_hanging_velocity_iterations << EOD
10 387.3 0.1941 1.158 1.845 0.5403 0.4824 1.804e+06 NaN 1
EOD
$mass_range_hanging_position_iterations << EOD
2 387.3 0.1941 1.158 1.845 0.5403 0.4824 1.804e+06 NaN 1
4 588.9 0.2027 1.201 1.641 0.5215 0.5368 9.691e+05 NaN 0
10 1244 0.2295 2.203 4.775 0.5279 0.6021 3.952e+06 NaN 0
30 3372 0.2201 1.467 2.812 0.5985 0.9236 2.656e+06 NaN 0
EOD
$mass_range_hanging_default << EOD
0 387.3 0.1941 1.158 1.845 0.5403 0.4824 1.804e+06 NaN 1
EOD
$mass_range_hanging_grid << EOD
0 387.3 0.1941 1.158 1.845 0.5403 0.4824 1.804e+06 NaN 1
0 588.9 0.2027 1.201 1.641 0.5215 0.5368 9.691e+05 NaN 0
0 1244 0.2295 2.203 4.775 0.5279 0.6021 3.952e+06 NaN 0
0 3372 0.2201 1.467 2.812 0.5985 0.9236 2.656e+06 NaN 0
0 769.2 0.1821 1.119 3.407 0.4324 0.6081 2.106e+06 NaN 0
0 1168 0.208 1.456 2.402 0.7351 0.999 8.678e+05 NaN 0
0 2448 0.1868 1.168 1.56 0.4213 0.4133 1.146e+06 NaN 0
0 6729 0.19 1.689 6.362 0.4899 0.6267 4.551e+06 NaN 0
0 1499 0.255 1.424 7.737 0.7884 1.512 3.521e+06 NaN 0
0 2309 0.2628 1.974 8.366 0.7183 0.9039 2.023e+06 NaN 0
0 4869 0.2063 1.103 1.694 0.6189 1.061 5.224e+05 NaN 0
0 1.313e+04 0.1611 1.032 2.275 0.5909 0.7491 2.248e+06 NaN 0
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
1 696.2 0.0005568 0.00176 0.03519 0.05131 0.06005 14.69 NaN 1
2 1325 0.0005672 0.001822 0.0192 0.02514 0.03309 7.85 NaN 0
4 2593 0.0005792 0.001848 0.009823 0.01108 0.02705 3.554 NaN 0
EOD
$far_1e4_velocity_iterations << EOD
10 696.2 0.0005568 0.00176 0.03519 0.05131 0.06005 14.69 NaN 1
EOD
$far_1e4_position_iterations << EOD
2 696.2 0.0005568 0.00176 0.03519 0.05131 0.06005 14.69 NaN 1
4 1029 0.0005717 0.001685 0.03576 0.05227 0.05705 15.06 NaN 0
10 2122 0.0005393 0.001752 0.03452 0.05154 0.06041 14.42 NaN 0
30 5429 0.000529 0.001787 0.03384 0.05185 0.06423 14.32 NaN 0
EOD
$far_1e4_default << EOD
0 696.2 0.0005568 0.00176 0.03519 0.05131 0.06005 14.69 NaN 1
EOD
$far_1e4_grid << EOD
0 696.2 0.0005568 0.00176 0.03519 0.05131 0.06005 14.69 NaN 1
0 1029 0.0005717 0.001685 0.03576 0.05227 0.05705 15.06 NaN 0
0 2122 0.0005393 0.001752 0.03452 0.05154 0.06041 14.42 NaN 0
0 5429 0.000529 0.001787 0.03384 0.05185 0.06423 14.32 NaN 0
0 1325 0.0005672 0.001822 0.0192 0.02514 0.03309 7.85 NaN 0
0 2000 0.0005435 0.001774 0.01922 0.02561 0.03174 8.365 NaN 0
0 4111 0.0005602 0.001656 0.01864 0.0248 0.03783 7.322 NaN 0
0 1.05e+04 0.0005262 0.001801 0.01733 0.02504 0.05072 6.513 NaN 0
0 2593 0.0005792 0.001848 0.009823 0.01108 0.02705 3.554 NaN 0
0 4026 0.0005778 0.001894 0.00955 0.01258 0.03534 3.13 NaN 0
0 7941 0.0005409 0.00215 0.01031 0.01312 0.03176 4.029 NaN 0
0 2.108e+04 0.0005408 0.001725 0.009701 0.01558 0.03756 4.324 NaN 0
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
1 649.1 0.02734 0.1314 0.2924 0.2921 0.2127 1225 NaN 1
2 1176 0.00543 0.06692 0.07733 0.04517 0.1068 551 NaN 0
4 1786 2.488e-06 9.894e-06 0.002264 0.0212 0.01364 242.1 NaN 0
EOD
$chain16_r1000_velocity_iterations << EOD
10 649.1 0.02734 0.1314 0.2924 0.2921 0.2127 1225 NaN 1
EOD
$chain16_r1000_position_iterations << EOD
2 649.1 0.02734 0.1314 0.2924 0.2921 0.2127 1225 NaN 1
4 870.7 0.0277 0.2144 0.3821 0.2809 0.1825 1060 NaN 0
10 1179 2.371e-06 9.586e-06 0.007279 0.04481 0.01852 898.8 NaN 0
30 1171 2.371e-06 9.586e-06 0.007279 0.04481 0.01852 898.8 NaN 0
EOD
$chain16_r1000_default << EOD
0 649.1 0.02734 0.1314 0.2924 0.2921 0.2127 1225 NaN 1
EOD
$chain16_r1000_grid << EOD
0 649.1 0.02734 0.1314 0.2924 0.2921 0.2127 1225 NaN 1
0 870.7 0.0277 0.2144 0.3821 0.2809 0.1825 1060 NaN 0
0 1179 2.371e-06 9.586e-06 0.007279 0.04481 0.01852 898.8 NaN 0
0 1171 2.371e-06 9.586e-06 0.007279 0.04481 0.01852 898.8 NaN 0
0 1176 0.00543 0.06692 0.07733 0.04517 0.1068 551 NaN 0
0 1388 4.435e-06 4.971e-05 0.004267 0.02602 0.01478 468.4 NaN 0
0 1393 1.59e-06 9.897e-06 0.004061 0.026 0.01456 465.2 NaN 0
0 1394 1.59e-06 9.897e-06 0.004061 0.026 0.01456 465.2 NaN 0
0 1786 2.488e-06 9.894e-06 0.002264 0.0212 0.01364 242.1 NaN 0
0 1804 2.488e-06 9.894e-06 0.002264 0.0212 0.01364 242.1 NaN 0
0 1790 2.488e-06 9.894e-06 0.002264 0.0212 0.01364 242.1 NaN 0
0 1776 2.488e-06 9.894e-06 0.002264 0.0212 0.01364 242.1 NaN 0
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
1 3585 2.448e-07 6.403e-06 0.005145 0.04924 0.02954 48.99 NaN 1
2 5688 1.689e-07 1.989e-06 0.002684 0.0244 0.01582 24.86 NaN 0
4 1.079e+04 3.725e-07 9.376e-06 0.001368 0.01088 0.007965 12.57 NaN 0
EOD
$chain64_velocity_iterations << EOD
10 3585 2.448e-07 6.403e-06 0.005145 0.04924 0.02954 48.99 NaN 1
EOD
$chain64_position_iterations << EOD
2 3585 2.448e-07 6.403e-06 0.005145 0.04924 0.02954 48.99 NaN 1
4 3609 2.448e-07 6.403e-06 0.005145 0.04924 0.02954 48.99 NaN 0
10 3692 2.448e-07 6.403e-06 0.005145 0.04924 0.02954 48.99 NaN 0
30 3612 2.448e-07 6.403e-06 0.005145 0.04924 0.02954 48.99 NaN 0
EOD
$chain64_default << EOD
0 3585 2.448e-07 6.403e-06 0.005145 0.04924 0.02954 48.99 NaN 1
EOD
$chain64_grid << EOD
0 3585 2.448e-07 6.403e-06 0.005145 0.04924 0.02954 48.99 NaN 1
0 3609 2.448e-07 6.403e-06 0.005145 0.04924 0.02954 48.99 NaN 0
0 3692 2.448e-07 6.403e-06 0.005145 0.04924 0.02954 48.99 NaN 0
0 3612 2.448e-07 6.403e-06 0.005145 0.04924 0.02954 48.99 NaN 0
0 5688 1.689e-07 1.989e-06 0.002684 0.0244 0.01582 24.86 NaN 0
0 5705 1.689e-07 1.989e-06 0.002684 0.0244 0.01582 24.86 NaN 0
0 5903 1.689e-07 1.989e-06 0.002684 0.0244 0.01582 24.86 NaN 0
0 5860 1.689e-07 1.989e-06 0.002684 0.0244 0.01582 24.86 NaN 0
0 1.079e+04 3.725e-07 9.376e-06 0.001368 0.01088 0.007965 12.57 NaN 0
0 1.085e+04 3.725e-07 9.376e-06 0.001368 0.01088 0.007965 12.57 NaN 0
0 1.094e+04 3.725e-07 9.376e-06 0.001368 0.01088 0.007965 12.57 NaN 0
0 1.084e+04 3.725e-07 9.376e-06 0.001368 0.01088 0.007965 12.57 NaN 0
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
