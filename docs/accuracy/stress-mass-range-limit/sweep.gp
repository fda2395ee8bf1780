# Error against ns per world-step, one curve per knob: written by
# ./build/tools/manyworlds sweep --scenes mass-range-hanging --worlds 256 --passes 2 --mass-range-limit 1000 --out docs/accuracy/stress-mass-range-limit
# Run: gnuplot sweep.gp (in this directory).
set terminal pngcairo noenhanced size 1500,900 font ',10'
set logscale xy
set grid
set format y '%.0e'
set key below horizontal
set xlabel 'ns per world-step (256 worlds, 1 thread(s), AVX3)'
$mass_range_hanging_substeps << EOD
1 439.6 0.08831 0.3222 0.6987 0.8005 0.4263 3.352e+06 NaN 1
2 870.6 0.0683 0.2435 0.6767 0.644 0.2249 7.654e+06 NaN 0
4 1722 0.02786 0.09912 0.3236 0.2683 0.08097 7.57e+06 NaN 0
8 3435 0.005156 0.01316 0.01407 0.04809 0.01866 1.334e+06 NaN 0
EOD
$mass_range_hanging_velocity_iterations << EOD
1 316.2 0.09646 0.3327 0.4419 0.9046 0.5321 2.103e+06 NaN 0
2 333.7 0.09217 0.3291 0.363 0.8647 0.495 3.085e+06 NaN 0
4 360.1 0.09022 0.309 0.5671 0.831 0.4597 3.389e+06 NaN 0
8 414.4 0.08869 0.3112 0.6429 0.8079 0.4364 3.491e+06 NaN 0
10 439.6 0.08831 0.3222 0.6987 0.8005 0.4263 3.352e+06 NaN 1
EOD
$mass_range_hanging_position_iterations << EOD
0 246.9 0.1061 0.5181 1.005 0.8165 0.4734 1.928e+06 NaN 0
1 347.2 0.09146 0.3626 0.8437 0.8056 0.4407 2.699e+06 NaN 0
2 439.6 0.08831 0.3222 0.6987 0.8005 0.4263 3.352e+06 NaN 1
EOD
$mass_range_hanging_default << EOD
0 439.6 0.08831 0.3222 0.6987 0.8005 0.4263 3.352e+06 NaN 1
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
