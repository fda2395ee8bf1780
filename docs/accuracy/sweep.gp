# Error against ns per world-step, one curve per knob: written by
# ./build/tools/manyworlds sweep --threads 1 --grid full --out docs/accuracy
# Run: gnuplot sweep.gp (in this directory).
set terminal pngcairo noenhanced size 1500,900 font ',10'
set logscale xy
set grid
set format y '%.0e'
set key below horizontal
set xlabel 'ns per world-step (1024 worlds, 1 thread(s), AVX3)'
$cartpole_substeps << EOD
1 160.4 0.001723 0.007978 0.1219 0.008632 0.01786 NaN NaN 1
2 313.4 0.0004781 0.002221 0.06362 0.004047 0.008417 NaN NaN 0
4 620.2 0.0001258 0.0005845 0.03254 0.001752 0.003628 NaN NaN 0
8 1240 3.226e-05 0.0001492 0.01646 0.0005922 0.001222 NaN NaN 0
EOD
$cartpole_velocity_iterations << EOD
1 111.3 0.001745 0.008102 0.1217 0.008657 0.01792 NaN NaN 0
2 114.6 0.001724 0.007986 0.1219 0.00863 0.01786 NaN NaN 0
4 130 0.001723 0.007978 0.1219 0.008632 0.01786 NaN NaN 0
8 152.7 0.001723 0.007978 0.1219 0.008632 0.01786 NaN NaN 0
10 160.4 0.001723 0.007978 0.1219 0.008632 0.01786 NaN NaN 1
EOD
$cartpole_position_iterations << EOD
0 88.4 0.01128 0.05582 0.1226 0.01458 0.01811 NaN NaN 0
1 128.7 0.003292 0.01538 0.1216 0.009456 0.01831 NaN NaN 0
2 160.4 0.001723 0.007978 0.1219 0.008632 0.01786 NaN NaN 1
EOD
$cartpole_default << EOD
0 160.4 0.001723 0.007978 0.1219 0.008632 0.01786 NaN NaN 1
EOD
$cartpole_grid << EOD
0 40.85 0.01127 0.05576 0.1224 0.01484 0.01807 NaN NaN 0
0 76.84 0.003324 0.0156 0.1215 0.009551 0.01843 NaN NaN 0
0 111.3 0.001745 0.008102 0.1217 0.008657 0.01792 NaN NaN 0
0 46.61 0.01128 0.05582 0.1226 0.0146 0.01811 NaN NaN 0
0 80.34 0.003294 0.01539 0.1216 0.009459 0.01831 NaN NaN 0
0 114.6 0.001724 0.007986 0.1219 0.00863 0.01786 NaN NaN 0
0 57.96 0.01128 0.05582 0.1226 0.01458 0.01811 NaN NaN 0
0 90.54 0.003292 0.01538 0.1216 0.009456 0.01831 NaN NaN 0
0 130 0.001723 0.007978 0.1219 0.008632 0.01786 NaN NaN 0
0 82 0.01128 0.05582 0.1226 0.01458 0.01811 NaN NaN 0
0 117.4 0.003292 0.01538 0.1216 0.009456 0.01831 NaN NaN 0
0 152.7 0.001723 0.007978 0.1219 0.008632 0.01786 NaN NaN 0
0 88.4 0.01128 0.05582 0.1226 0.01458 0.01811 NaN NaN 0
0 128.7 0.003292 0.01538 0.1216 0.009456 0.01831 NaN NaN 0
0 160.4 0.001723 0.007978 0.1219 0.008632 0.01786 NaN NaN 1
0 71.31 0.005658 0.02851 0.0637 0.007471 0.008559 NaN NaN 0
0 139.8 0.0009933 0.004699 0.06352 0.004202 0.008608 NaN NaN 0
0 202.1 0.0004811 0.002234 0.06359 0.004041 0.008413 NaN NaN 0
0 81.58 0.005659 0.02852 0.06373 0.007403 0.008566 NaN NaN 0
0 151.9 0.0009876 0.00467 0.06354 0.004195 0.008595 NaN NaN 0
0 212.2 0.0004782 0.002221 0.06362 0.004046 0.008416 NaN NaN 0
0 103.9 0.005659 0.02852 0.06373 0.007399 0.008566 NaN NaN 0
0 174 0.0009873 0.004668 0.06354 0.004195 0.008595 NaN NaN 0
0 244.3 0.0004781 0.002221 0.06362 0.004047 0.008417 NaN NaN 0
0 149.2 0.005659 0.02852 0.06373 0.007399 0.008567 NaN NaN 0
0 217.3 0.0009873 0.004668 0.06354 0.004195 0.008595 NaN NaN 0
0 282.4 0.0004781 0.002221 0.06362 0.004047 0.008417 NaN NaN 0
0 170.1 0.005659 0.02852 0.06373 0.007399 0.008567 NaN NaN 0
0 242 0.0009873 0.004668 0.06354 0.004195 0.008595 NaN NaN 0
0 313.4 0.0004781 0.002221 0.06362 0.004047 0.008417 NaN NaN 0
0 130.7 0.002836 0.01443 0.03255 0.003693 0.003698 NaN NaN 0
0 273.2 0.0002721 0.001276 0.03252 0.001759 0.00366 NaN NaN 0
0 404.7 0.0001262 0.000585 0.03253 0.001748 0.003624 NaN NaN 0
0 161.1 0.002836 0.01443 0.03255 0.003675 0.003699 NaN NaN 0
0 298 0.0002713 0.001275 0.03252 0.00176 0.003661 NaN NaN 0
0 433.6 0.0001258 0.0005845 0.03254 0.001751 0.003628 NaN NaN 0
0 199.1 0.002836 0.01443 0.03255 0.003674 0.0037 NaN NaN 0
0 337.4 0.0002713 0.001275 0.03252 0.00176 0.003661 NaN NaN 0
0 470.8 0.0001258 0.0005845 0.03254 0.001752 0.003628 NaN NaN 0
0 282.5 0.002836 0.01443 0.03255 0.003674 0.0037 NaN NaN 0
0 430 0.0002713 0.001275 0.03252 0.00176 0.003661 NaN NaN 0
0 566.8 0.0001258 0.0005845 0.03254 0.001752 0.003628 NaN NaN 0
0 333.3 0.002836 0.01443 0.03255 0.003674 0.0037 NaN NaN 0
0 472.3 0.0002713 0.001275 0.03252 0.00176 0.003661 NaN NaN 0
0 620.2 0.0001258 0.0005845 0.03254 0.001752 0.003628 NaN NaN 0
0 254.8 0.00142 0.007258 0.01646 0.001809 0.001238 NaN NaN 0
0 538.9 7.097e-05 0.0003306 0.01645 0.0005844 0.001216 NaN NaN 0
0 834.4 3.23e-05 0.0001492 0.01646 0.0005914 0.001222 NaN NaN 0
0 306.2 0.00142 0.007258 0.01646 0.001804 0.001238 NaN NaN 0
0 578.2 7.089e-05 0.0003305 0.01645 0.000585 0.001217 NaN NaN 0
0 869 3.226e-05 0.0001492 0.01646 0.0005921 0.001222 NaN NaN 0
0 387.3 0.00142 0.007257 0.01646 0.001804 0.001238 NaN NaN 0
0 669.5 7.088e-05 0.0003305 0.01646 0.0005851 0.001217 NaN NaN 0
0 962.5 3.226e-05 0.0001493 0.01646 0.0005922 0.001222 NaN NaN 0
0 571.1 0.00142 0.007257 0.01646 0.001804 0.001238 NaN NaN 0
0 853 7.088e-05 0.0003305 0.01646 0.0005851 0.001217 NaN NaN 0
0 1147 3.226e-05 0.0001493 0.01646 0.0005922 0.001223 NaN NaN 0
0 652.2 0.00142 0.007258 0.01646 0.001804 0.001238 NaN NaN 0
0 951.8 7.088e-05 0.0003304 0.01645 0.0005851 0.001217 NaN NaN 0
0 1240 3.226e-05 0.0001492 0.01646 0.0005922 0.001222 NaN NaN 0
EOD
set output 'cartpole.png'
set multiplot layout 2,3 title 'cartpole: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $cartpole_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $cartpole_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $cartpole_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $cartpole_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $cartpole_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $cartpole_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $cartpole_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $cartpole_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $cartpole_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $cartpole_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $cartpole_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $cartpole_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $cartpole_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $cartpole_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $cartpole_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $cartpole_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $cartpole_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $cartpole_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $cartpole_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $cartpole_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $cartpole_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $cartpole_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $cartpole_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $cartpole_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $cartpole_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $cartpole_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $cartpole_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $cartpole_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $cartpole_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $cartpole_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $cartpole_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $cartpole_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $cartpole_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $cartpole_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $cartpole_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $cartpole_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $cartpole_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $cartpole_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $cartpole_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $cartpole_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$chain16_substeps << EOD
1 701 0.005789 0.01548 0.04159 0.07229 0.02415 24.65 NaN 1
2 1356 0.002195 0.006265 0.02098 0.02813 0.01029 11.09 NaN 0
4 2753 0.0008504 0.002335 0.01074 0.01116 0.003688 5.254 NaN 0
8 5514 0.0003096 0.0007788 0.005444 0.003754 0.001267 2.485 NaN 0
EOD
$chain16_velocity_iterations << EOD
1 524.7 0.02172 0.05961 0.1056 0.3119 0.1402 61.34 NaN 0
2 519 0.01344 0.03634 0.05879 0.1868 0.07281 43.66 NaN 0
4 570.4 0.008746 0.0219 0.04691 0.1159 0.03703 32.43 NaN 0
8 659.4 0.006292 0.01612 0.04232 0.07936 0.02567 26.01 NaN 0
10 701 0.005789 0.01548 0.04159 0.07229 0.02415 24.65 NaN 1
EOD
$chain16_position_iterations << EOD
0 412 0.006737 0.0207 0.04752 0.074 0.02736 27.02 NaN 0
1 561.6 0.006119 0.01688 0.04299 0.07434 0.02458 25.37 NaN 0
2 701 0.005789 0.01548 0.04159 0.07229 0.02415 24.65 NaN 1
EOD
$chain16_default << EOD
0 701 0.005789 0.01548 0.04159 0.07229 0.02415 24.65 NaN 1
EOD
$chain16_grid << EOD
0 207.8 0.0415 0.1146 0.209 0.3394 0.2243 88.71 NaN 0
0 376.1 0.02308 0.06399 0.1172 0.3236 0.1595 65.24 NaN 0
0 524.7 0.02172 0.05961 0.1056 0.3119 0.1402 61.34 NaN 0
0 238.5 0.01544 0.03785 0.07994 0.203 0.09988 50.74 NaN 0
0 376.2 0.01431 0.03917 0.06248 0.1945 0.08012 45.43 NaN 0
0 519 0.01344 0.03634 0.05879 0.1868 0.07281 43.66 NaN 0
0 274.7 0.01029 0.02673 0.05818 0.1221 0.05081 36.99 NaN 0
0 445.9 0.009272 0.02308 0.04936 0.1203 0.04126 33.64 NaN 0
0 570.4 0.008746 0.0219 0.04691 0.1159 0.03703 32.43 NaN 0
0 361.8 0.007343 0.02165 0.04911 0.08179 0.03091 28.75 NaN 0
0 505.7 0.006657 0.01748 0.04392 0.08185 0.02671 26.82 NaN 0
0 659.4 0.006292 0.01612 0.04232 0.07936 0.02567 26.01 NaN 0
0 412 0.006737 0.0207 0.04752 0.074 0.02736 27.02 NaN 0
0 561.6 0.006119 0.01688 0.04299 0.07434 0.02458 25.37 NaN 0
0 701 0.005789 0.01548 0.04159 0.07229 0.02415 24.65 NaN 1
0 376.5 0.01102 0.02935 0.04913 0.09817 0.05398 28.23 NaN 0
0 676.9 0.006858 0.01802 0.0374 0.1001 0.03411 24.04 NaN 0
0 970.3 0.00623 0.01642 0.03521 0.09422 0.03061 22.94 NaN 0
0 421.1 0.00484 0.01209 0.02791 0.0624 0.02573 18.56 NaN 0
0 717.4 0.004483 0.01163 0.02503 0.06047 0.02389 17.21 NaN 0
0 1002 0.004043 0.0105 0.02404 0.05683 0.02208 16.56 NaN 0
0 510.2 0.003545 0.0104 0.02373 0.04001 0.01554 14.48 NaN 0
0 805.1 0.003174 0.008305 0.02214 0.03999 0.01718 13.62 NaN 0
0 1105 0.002877 0.007186 0.02158 0.03798 0.01688 13.18 NaN 0
0 711.3 0.002863 0.009373 0.02276 0.03059 0.01211 12.35 NaN 0
0 1028 0.002543 0.007505 0.02147 0.0308 0.01147 11.76 NaN 0
0 1297 0.002305 0.006397 0.02102 0.02958 0.01163 11.44 NaN 0
0 774.6 0.002735 0.009222 0.02268 0.02913 0.01144 11.93 NaN 0
0 1057 0.002423 0.007368 0.02142 0.02921 0.01026 11.39 NaN 0
0 1356 0.002195 0.006265 0.02098 0.02813 0.01029 11.09 NaN 0
0 740 0.003119 0.008156 0.0156 0.02832 0.01491 9.58 NaN 0
0 1333 0.002023 0.005227 0.01405 0.02878 0.01596 8.65 NaN 0
0 1946 0.001712 0.004443 0.01356 0.02588 0.01634 8.235 NaN 0
0 845.7 0.001701 0.005063 0.01201 0.01974 0.008965 7.256 NaN 0
0 1415 0.001457 0.00369 0.01146 0.01878 0.009866 6.795 NaN 0
0 2062 0.001227 0.002952 0.01124 0.01698 0.01049 6.524 NaN 0
0 1027 0.001427 0.004711 0.01154 0.01476 0.006584 6.207 NaN 0
0 1587 0.00117 0.003306 0.01105 0.01421 0.005644 5.863 NaN 0
0 2229 0.0009857 0.002524 0.01086 0.01303 0.005993 5.658 NaN 0
0 1415 0.001282 0.004497 0.01139 0.01328 0.006595 5.817 NaN 0
0 1951 0.001038 0.003134 0.01093 0.01232 0.004301 5.516 NaN 0
0 2773 0.0008723 0.002364 0.01075 0.01143 0.00392 5.329 NaN 0
0 1595 0.001254 0.004458 0.01136 0.01305 0.006814 5.733 NaN 0
0 2199 0.001012 0.003101 0.01091 0.01198 0.004166 5.439 NaN 0
0 2753 0.0008504 0.002335 0.01074 0.01116 0.003688 5.254 NaN 0
0 1439 0.00102 0.002879 0.006392 0.008854 0.005238 3.617 NaN 0
0 2656 0.000617 0.001471 0.006089 0.008135 0.004688 3.291 NaN 0
0 3846 0.0004685 0.001155 0.005997 0.006744 0.005593 3.132 NaN 0
0 1668 0.0007032 0.002355 0.005928 0.007233 0.004893 3.253 NaN 0
0 2856 0.0005009 0.001304 0.005723 0.005914 0.002662 3 NaN 0
0 4062 0.0003794 0.0009518 0.005644 0.004917 0.002807 2.864 NaN 0
0 2024 0.0006431 0.002254 0.005736 0.00634 0.005358 2.953 NaN 0
0 3197 0.0004427 0.001212 0.005557 0.004908 0.002151 2.737 NaN 0
0 4479 0.0003355 0.0008286 0.005493 0.00414 0.001514 2.619 NaN 0
0 2849 0.000606 0.002195 0.00568 0.005977 0.005449 2.816 NaN 0
0 3961 0.000414 0.001168 0.005512 0.00446 0.002175 2.618 NaN 0
0 5226 0.0003139 0.000787 0.005451 0.003813 0.001286 2.507 NaN 0
0 3181 0.0005987 0.002186 0.00567 0.005911 0.005463 2.789 NaN 0
0 4290 0.0004081 0.00116 0.005504 0.004382 0.002202 2.594 NaN 0
0 5514 0.0003096 0.0007788 0.005444 0.003754 0.001267 2.485 NaN 0
EOD
set output 'chain16.png'
set multiplot layout 2,3 title 'chain16: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $chain16_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $chain16_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $chain16_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $chain16_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $chain16_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $chain16_grid using 2:8 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$chain16_r100_substeps << EOD
1 714.6 0.01663 0.05675 0.1621 0.2656 0.1965 413.3 NaN 1
2 1362 0.00689 0.02207 0.0335 0.1141 0.08704 415.4 NaN 0
4 2765 0.002235 0.005899 0.01277 0.03929 0.04 134.6 NaN 0
8 5496 0.0005966 0.001781 0.006479 0.0124 0.01369 42.46 NaN 0
EOD
$chain16_r100_velocity_iterations << EOD
1 517.7 0.04483 0.1179 0.1795 0.7583 0.4412 358.9 NaN 0
2 548.5 0.03378 0.08108 0.119 0.5776 0.409 389.5 NaN 0
4 591.5 0.02505 0.06672 0.09275 0.4207 0.3323 466 NaN 0
8 664.8 0.01834 0.05835 0.1541 0.2973 0.2257 449.2 NaN 0
10 714.6 0.01663 0.05675 0.1621 0.2656 0.1965 413.3 NaN 1
EOD
$chain16_r100_position_iterations << EOD
0 421.6 0.01773 0.07195 0.1835 0.2702 0.197 420 NaN 0
1 561.6 0.01697 0.06502 0.1786 0.2679 0.1993 414.8 NaN 0
2 714.6 0.01663 0.05675 0.1621 0.2656 0.1965 413.3 NaN 1
EOD
$chain16_r100_default << EOD
0 714.6 0.01663 0.05675 0.1621 0.2656 0.1965 413.3 NaN 1
EOD
$chain16_r100_grid << EOD
0 218.7 0.0642 0.212 0.3582 0.7601 0.5063 366.4 NaN 0
0 363.4 0.0456 0.1222 0.2039 0.7591 0.4512 360.8 NaN 0
0 517.7 0.04483 0.1179 0.1795 0.7583 0.4412 358.9 NaN 0
0 242.3 0.03526 0.1026 0.1433 0.5802 0.4298 399.5 NaN 0
0 386.2 0.03416 0.08383 0.1205 0.5825 0.4154 389.1 NaN 0
0 548.5 0.03378 0.08108 0.119 0.5776 0.409 389.5 NaN 0
0 289.6 0.02669 0.07948 0.1923 0.4232 0.337 453.8 NaN 0
0 432.3 0.02526 0.06751 0.09488 0.4233 0.3355 467.3 NaN 0
0 591.5 0.02505 0.06672 0.09275 0.4207 0.3323 466 NaN 0
0 377.5 0.01963 0.08059 0.2024 0.3015 0.2255 442.1 NaN 0
0 523.1 0.0187 0.06278 0.1779 0.3 0.2289 422 NaN 0
0 664.8 0.01834 0.05835 0.1541 0.2973 0.2257 449.2 NaN 0
0 421.6 0.01773 0.07195 0.1835 0.2702 0.197 420 NaN 0
0 561.6 0.01697 0.06502 0.1786 0.2679 0.1993 414.8 NaN 0
0 714.6 0.01663 0.05675 0.1621 0.2656 0.1965 413.3 NaN 1
0 388.8 0.03306 0.1049 0.1904 0.4026 0.3262 546.4 NaN 0
0 677.5 0.0243 0.06984 0.1219 0.4046 0.3287 439.2 NaN 0
0 995.5 0.024 0.06786 0.1174 0.4012 0.3233 433.5 NaN 0
0 438.1 0.01761 0.04767 0.07785 0.2842 0.2233 468.1 NaN 0
0 732.4 0.0171 0.04922 0.07295 0.2818 0.221 467.6 NaN 0
0 1034 0.01692 0.04791 0.07222 0.2789 0.2171 467.7 NaN 0
0 533.3 0.01199 0.03491 0.05728 0.1913 0.1374 504.7 NaN 0
0 825.8 0.01158 0.0374 0.05384 0.19 0.1402 482.1 NaN 0
0 1121 0.01146 0.03648 0.05321 0.1882 0.1383 479.8 NaN 0
0 707.2 0.008108 0.02367 0.04071 0.1304 0.0956 463.3 NaN 0
0 999.6 0.007905 0.02595 0.03872 0.1302 0.09828 449.3 NaN 0
0 1294 0.007831 0.02527 0.03819 0.1291 0.09738 446.9 NaN 0
0 779.5 0.007107 0.02071 0.03569 0.1149 0.08502 430.2 NaN 0
0 1084 0.006952 0.02269 0.03396 0.1151 0.08768 418 NaN 0
0 1362 0.00689 0.02207 0.0335 0.1141 0.08704 415.4 NaN 0
0 753.1 0.01336 0.04011 0.07052 0.1801 0.1247 532.7 NaN 0
0 1302 0.01094 0.03594 0.0597 0.1808 0.1362 457.8 NaN 0
0 1990 0.01078 0.03479 0.05867 0.1785 0.1335 453.8 NaN 0
0 823.6 0.007561 0.02289 0.03817 0.1248 0.09973 420.8 NaN 0
0 1444 0.007368 0.02468 0.03681 0.1232 0.09884 419.4 NaN 0
0 2035 0.007267 0.02392 0.03645 0.1218 0.09746 417.6 NaN 0
0 1012 0.004811 0.01369 0.02261 0.0802 0.06835 296.4 NaN 0
0 1632 0.004717 0.01476 0.02191 0.08065 0.07013 289 NaN 0
0 2232 0.004659 0.01426 0.02169 0.0798 0.06963 286.7 NaN 0
0 1405 0.002772 0.007162 0.01432 0.04717 0.04494 163.3 NaN 0
0 1962 0.002736 0.007483 0.0141 0.04777 0.04637 161 NaN 0
0 2676 0.002704 0.007244 0.01402 0.04728 0.04622 160 NaN 0
0 1541 0.002287 0.00602 0.01295 0.03911 0.03877 137.1 NaN 0
0 2161 0.002262 0.006054 0.01282 0.0397 0.04009 135.3 NaN 0
0 2765 0.002235 0.005899 0.01277 0.03929 0.04 134.6 NaN 0
0 1438 0.005035 0.0155 0.02642 0.07464 0.06482 286.5 NaN 0
0 2728 0.00444 0.01388 0.02406 0.07741 0.07066 270.4 NaN 0
0 3963 0.004358 0.01334 0.02362 0.07623 0.07001 267.9 NaN 0
0 1649 0.002553 0.006585 0.01385 0.04521 0.04714 144.1 NaN 0
0 2928 0.002487 0.006957 0.01373 0.04471 0.04719 143 NaN 0
0 4236 0.002438 0.006722 0.01366 0.04402 0.04694 142 NaN 0
0 2075 0.001315 0.003614 0.01004 0.02474 0.02939 82.2 NaN 0
0 3332 0.001291 0.00364 0.01005 0.02459 0.03023 81.26 NaN 0
0 4554 0.001266 0.003536 0.01004 0.02433 0.03019 80.78 NaN 0
0 2941 0.0007244 0.002176 0.007234 0.015 0.01732 51.57 NaN 0
0 4350 0.0007127 0.002166 0.007218 0.01489 0.01781 51.16 NaN 0
0 5226 0.0006985 0.002086 0.007208 0.0148 0.01775 50.93 NaN 0
0 3191 0.0006181 0.001832 0.006509 0.01256 0.0134 42.94 NaN 0
0 4397 0.0006093 0.001868 0.006488 0.0125 0.01375 42.66 NaN 0
0 5496 0.0005966 0.001781 0.006479 0.0124 0.01369 42.46 NaN 0
EOD
set output 'chain16-r100.png'
set multiplot layout 2,3 title 'chain16-r100: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $chain16_r100_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r100_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r100_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r100_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r100_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r100_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r100_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r100_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $chain16_r100_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r100_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r100_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r100_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r100_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r100_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r100_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r100_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $chain16_r100_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r100_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r100_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r100_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r100_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r100_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r100_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r100_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $chain16_r100_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r100_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r100_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r100_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r100_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r100_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r100_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r100_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $chain16_r100_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r100_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r100_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r100_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r100_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r100_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r100_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r100_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'energy drift max (J)'
plot $chain16_r100_grid using 2:8 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $chain16_r100_substeps using 2:8 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $chain16_r100_substeps using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $chain16_r100_velocity_iterations using 2:8 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $chain16_r100_velocity_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $chain16_r100_position_iterations using 2:8 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $chain16_r100_position_iterations using 2:8:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $chain16_r100_default using 2:8 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$chain16_r1000_substeps << EOD
1 734.7 0.03406 0.1224 0.2985 0.5814 0.3068 1769 NaN 1
2 1433 0.02625 0.08994 0.2528 0.4306 0.173 3069 NaN 0
4 2993 0.01343 0.04133 0.09186 0.218 0.08325 4077 NaN 0
8 5567 0.003423 0.007775 0.01029 0.05499 0.03082 981.7 NaN 0
EOD
$chain16_r1000_velocity_iterations << EOD
1 510.6 0.04831 0.1288 0.1969 0.9278 0.4722 1141 NaN 0
2 527.7 0.03984 0.107 0.1528 0.796 0.4151 1306 NaN 0
4 574.7 0.03581 0.1129 0.3329 0.6855 0.3636 1630 NaN 0
8 674.7 0.03445 0.1247 0.3165 0.6031 0.32 1723 NaN 0
10 734.7 0.03406 0.1224 0.2985 0.5814 0.3068 1769 NaN 1
EOD
$chain16_r1000_position_iterations << EOD
0 430.4 0.03734 0.1785 0.3453 0.5852 0.3124 1606 NaN 0
1 575.3 0.03429 0.1342 0.3274 0.5829 0.3099 1675 NaN 0
2 734.7 0.03406 0.1224 0.2985 0.5814 0.3068 1769 NaN 1
EOD
$chain16_r1000_default << EOD
0 734.7 0.03406 0.1224 0.2985 0.5814 0.3068 1769 NaN 1
EOD
$chain16_r1000_grid << EOD
0 215.9 0.0675 0.2281 0.3844 0.9434 0.568 1123 NaN 0
0 367.7 0.04898 0.133 0.2289 0.9289 0.4816 1141 NaN 0
0 510.6 0.04831 0.1288 0.1969 0.9278 0.4722 1141 NaN 0
0 240.2 0.04131 0.1285 0.1802 0.7965 0.4264 1303 NaN 0
0 385.3 0.04012 0.1085 0.1538 0.7991 0.4173 1302 NaN 0
0 527.7 0.03984 0.107 0.1528 0.796 0.4151 1306 NaN 0
0 291.5 0.03853 0.1417 0.3654 0.6877 0.37 1489 NaN 0
0 436.9 0.03618 0.1354 0.3426 0.6869 0.3653 1609 NaN 0
0 574.7 0.03581 0.1129 0.3329 0.6855 0.3636 1630 NaN 0
0 376.3 0.03724 0.172 0.3608 0.6062 0.3249 1608 NaN 0
0 522.6 0.03488 0.1459 0.3202 0.6045 0.3229 1663 NaN 0
0 674.7 0.03445 0.1247 0.3165 0.6031 0.32 1723 NaN 0
0 430.4 0.03734 0.1785 0.3453 0.5852 0.3124 1606 NaN 0
0 575.3 0.03429 0.1342 0.3274 0.5829 0.3099 1675 NaN 0
0 734.7 0.03406 0.1224 0.2985 0.5814 0.3068 1769 NaN 1
0 395.6 0.0468 0.1486 0.2834 0.6712 0.3733 1614 NaN 0
0 697.7 0.03483 0.1135 0.1835 0.6724 0.3637 1395 NaN 0
0 985.7 0.03465 0.111 0.1794 0.6706 0.361 1386 NaN 0
0 430.1 0.03268 0.09236 0.152 0.5916 0.3125 1998 NaN 0
0 735.8 0.03199 0.1002 0.134 0.5907 0.3097 2061 NaN 0
0 1011 0.0319 0.09796 0.1332 0.5891 0.3079 2070 NaN 0
0 523.1 0.03127 0.1225 0.3421 0.5197 0.2508 2501 NaN 0
0 822 0.02981 0.1048 0.3278 0.5182 0.2486 2745 NaN 0
0 1127 0.02941 0.1027 0.3644 0.517 0.2486 3072 NaN 0
0 699.1 0.0296 0.1228 0.28 0.456 0.1942 2639 NaN 0
0 1019 0.02767 0.1023 0.2767 0.452 0.1924 2898 NaN 0
0 1307 0.02711 0.09372 0.2625 0.45 0.1908 3074 NaN 0
0 800.4 0.02882 0.1205 0.263 0.4369 0.1775 2700 NaN 0
0 1110 0.02702 0.1011 0.2588 0.4328 0.1751 2909 NaN 0
0 1433 0.02625 0.08994 0.2528 0.4306 0.173 3069 NaN 0
0 745.4 0.03473 0.1095 0.338 0.5116 0.2475 3530 NaN 0
0 1352 0.02877 0.09034 0.1416 0.5121 0.2465 3121 NaN 0
0 2126 0.02871 0.08846 0.1402 0.5109 0.2446 3107 NaN 0
0 893.4 0.0259 0.07334 0.1405 0.4392 0.1865 4488 NaN 0
0 1524 0.02538 0.07878 0.1076 0.4372 0.1844 4549 NaN 0
0 2185 0.02532 0.0769 0.1071 0.4362 0.1833 4552 NaN 0
0 1036 0.0216 0.0796 0.2909 0.352 0.1351 5422 NaN 0
0 1655 0.02074 0.0635 0.07914 0.349 0.1335 5656 NaN 0
0 2328 0.02069 0.062 0.07883 0.3483 0.1328 5640 NaN 0
0 1417 0.01666 0.06687 0.1399 0.2575 0.1 4226 NaN 0
0 2093 0.01553 0.05067 0.1039 0.2513 0.09601 4446 NaN 0
0 2806 0.01518 0.04494 0.08459 0.2484 0.09344 4545 NaN 0
0 1620 0.015 0.06125 0.1764 0.2289 0.09103 3910 NaN 0
0 2280 0.01381 0.04622 0.09089 0.2218 0.08563 4092 NaN 0
0 2993 0.01343 0.04133 0.09186 0.218 0.08325 4077 NaN 0
0 1442 0.02416 0.07465 0.1802 0.3482 0.1364 6565 NaN 0
0 2779 0.02048 0.06129 0.09477 0.3457 0.1324 5570 NaN 0
0 3964 0.02042 0.05978 0.09426 0.3447 0.1313 5546 NaN 0
0 1674 0.01493 0.03807 0.06486 0.2453 0.0916 4858 NaN 0
0 2999 0.01459 0.03986 0.05218 0.2422 0.09028 4800 NaN 0
0 4184 0.01453 0.03878 0.05191 0.2415 0.08963 4789 NaN 0
0 2042 0.008856 0.01975 0.02572 0.1421 0.05588 2717 NaN 0
0 3318 0.008597 0.02039 0.02435 0.1409 0.05521 2570 NaN 0
0 4644 0.008563 0.01984 0.02421 0.1404 0.0549 2560 NaN 0
0 2916 0.00442 0.009151 0.01224 0.0693 0.03491 1166 NaN 0
0 4023 0.004294 0.009372 0.01172 0.06893 0.03464 1106 NaN 0
0 5315 0.004273 0.009129 0.01165 0.06859 0.03446 1099 NaN 0
0 3338 0.003532 0.007687 0.01088 0.0556 0.03143 1030 NaN 0
0 4320 0.003441 0.007975 0.01038 0.05528 0.03097 987.6 NaN 0
0 5567 0.003423 0.007775 0.01029 0.05499 0.03082 981.7 NaN 0
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
1 4056 0.00544 0.01668 0.01637 0.2438 0.1077 131.1 NaN 1
2 7158 0.001565 0.004718 0.005285 0.07465 0.03267 47.21 NaN 0
4 1.279e+04 0.0004628 0.001427 0.001822 0.02094 0.01258 18.79 NaN 0
8 2.528e+04 0.0001479 0.0004778 0.0007851 0.005407 0.00559 8.14 NaN 0
EOD
$chain64_velocity_iterations << EOD
1 3042 0.01915 0.08694 0.07609 0.6444 0.3136 253 NaN 0
2 3100 0.01454 0.05765 0.04447 0.5653 0.2611 260.5 NaN 0
4 3378 0.01029 0.03716 0.02871 0.4347 0.1984 225.1 NaN 0
8 3807 0.006457 0.02037 0.01863 0.2864 0.1277 150.7 NaN 0
10 4056 0.00544 0.01668 0.01637 0.2438 0.1077 131.1 NaN 1
EOD
$chain64_position_iterations << EOD
0 2591 0.005681 0.01694 0.01811 0.2463 0.1126 137.4 NaN 0
1 3390 0.005505 0.01717 0.01675 0.245 0.1093 132.8 NaN 0
2 4056 0.00544 0.01668 0.01637 0.2438 0.1077 131.1 NaN 1
EOD
$chain64_default << EOD
0 4056 0.00544 0.01668 0.01637 0.2438 0.1077 131.1 NaN 1
EOD
$chain64_grid << EOD
0 1486 0.02744 0.156 0.1286 0.6448 0.4108 268 NaN 0
0 2130 0.01952 0.09153 0.0827 0.6455 0.3377 256.2 NaN 0
0 3042 0.01915 0.08694 0.07609 0.6444 0.3136 253 NaN 0
0 1662 0.01498 0.05519 0.05136 0.5665 0.2977 266.6 NaN 0
0 2395 0.01473 0.0604 0.0453 0.5666 0.2707 261.6 NaN 0
0 3100 0.01454 0.05765 0.04447 0.5653 0.2611 260.5 NaN 0
0 1617 0.01067 0.03489 0.032 0.4369 0.2114 233.5 NaN 0
0 2687 0.0104 0.03852 0.02928 0.4359 0.2024 226.8 NaN 0
0 3378 0.01029 0.03716 0.02871 0.4347 0.1984 225.1 NaN 0
0 2309 0.006729 0.02024 0.02069 0.2889 0.134 157.9 NaN 0
0 3123 0.006529 0.02102 0.01906 0.2877 0.1297 152.5 NaN 0
0 3807 0.006457 0.02037 0.01863 0.2864 0.1277 150.7 NaN 0
0 2591 0.005681 0.01694 0.01811 0.2463 0.1126 137.4 NaN 0
0 3390 0.005505 0.01717 0.01675 0.245 0.1093 132.8 NaN 0
0 4056 0.00544 0.01668 0.01637 0.2438 0.1077 131.1 NaN 1
0 2470 0.01202 0.04627 0.04341 0.4386 0.2302 216.4 NaN 0
0 3855 0.009954 0.03565 0.03347 0.4372 0.2015 203.3 NaN 0
0 5072 0.009819 0.03385 0.03216 0.4355 0.1926 201.3 NaN 0
0 2572 0.006146 0.0179 0.01623 0.2857 0.131 123.8 NaN 0
0 4186 0.006064 0.01876 0.01522 0.2842 0.1265 120.2 NaN 0
0 5270 0.005968 0.01778 0.01501 0.2826 0.124 118.9 NaN 0
0 3159 0.003393 0.009437 0.00905 0.1625 0.07574 74.14 NaN 0
0 4429 0.003302 0.009857 0.008567 0.1616 0.07331 71.72 NaN 0
0 5641 0.003245 0.009418 0.008429 0.1605 0.07161 70.76 NaN 0
0 4077 0.00194 0.00576 0.006244 0.09082 0.04275 53.86 NaN 0
0 5396 0.001888 0.005814 0.005977 0.09047 0.04088 52.68 NaN 0
0 6626 0.001852 0.005592 0.005879 0.08976 0.03978 52.1 NaN 0
0 4679 0.00164 0.004931 0.005588 0.07549 0.03534 48.67 NaN 0
0 5707 0.001597 0.004899 0.00537 0.07526 0.03359 47.7 NaN 0
0 7158 0.001565 0.004718 0.005285 0.07465 0.03267 47.21 NaN 0
0 4196 0.003616 0.01159 0.009679 0.1582 0.07791 58.46 NaN 0
0 6437 0.00302 0.008509 0.008723 0.1573 0.0713 54.77 NaN 0
0 8913 0.002943 0.007953 0.008537 0.1556 0.06833 53.73 NaN 0
0 4522 0.001671 0.004822 0.004443 0.08619 0.04333 37.86 NaN 0
0 7002 0.001635 0.00483 0.004296 0.08533 0.04013 36.91 NaN 0
0 9540 0.001589 0.004518 0.004237 0.08432 0.03854 36.36 NaN 0
0 5456 0.0009412 0.002774 0.002803 0.04589 0.02438 26.37 NaN 0
0 7855 0.0009132 0.002768 0.002723 0.04563 0.02264 25.85 NaN 0
0 1.03e+04 0.0008858 0.002604 0.002684 0.0451 0.02204 25.53 NaN 0
0 7165 0.00057 0.001793 0.002029 0.02527 0.01526 20.43 NaN 0
0 9481 0.0005516 0.001707 0.001989 0.02518 0.01425 20.14 NaN 0
0 1.189e+04 0.0005337 0.001614 0.001966 0.02495 0.01396 19.94 NaN 0
0 7950 0.0004954 0.001598 0.001874 0.02119 0.01379 19.2 NaN 0
0 1.026e+04 0.0004788 0.001516 0.001841 0.02112 0.01293 18.96 NaN 0
0 1.279e+04 0.0004628 0.001427 0.001822 0.02094 0.01258 18.79 NaN 0
0 7006 0.0009334 0.003068 0.002462 0.04327 0.02591 18.84 NaN 0
0 1.182e+04 0.0007886 0.002254 0.002371 0.04308 0.02257 18.17 NaN 0
0 1.688e+04 0.0007539 0.002059 0.002341 0.04223 0.02182 17.8 NaN 0
0 8127 0.0004571 0.001341 0.001341 0.02275 0.01544 12.94 NaN 0
0 1.27e+04 0.0004389 0.001285 0.001315 0.02235 0.01424 12.64 NaN 0
0 1.776e+04 0.0004194 0.001174 0.001301 0.02203 0.01396 12.43 NaN 0
0 9701 0.000277 0.000871 0.0009576 0.01192 0.01129 10.06 NaN 0
0 1.448e+04 0.000262 0.0007945 0.0009447 0.01167 0.0106 9.885 NaN 0
0 1.898e+04 0.0002494 0.0007293 0.0009365 0.01152 0.01029 9.753 NaN 0
0 1.297e+04 0.000187 0.0006411 0.0008179 0.006601 0.006946 8.608 NaN 0
0 1.775e+04 0.0001744 0.0005739 0.0008114 0.006456 0.00675 8.499 NaN 0
0 2.259e+04 0.0001646 0.0005184 0.0008071 0.006369 0.006693 8.413 NaN 0
0 1.501e+04 0.0001695 0.0005963 0.0007937 0.005631 0.005695 8.312 NaN 0
0 1.938e+04 0.0001573 0.0005312 0.0007886 0.005488 0.005598 8.216 NaN 0
0 2.528e+04 0.0001479 0.0004778 0.0007851 0.005407 0.00559 8.14 NaN 0
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
$rackpinion_substeps << EOD
1 176.1 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 1
2 343 2.365e-07 1.008e-06 2.819e-08 0.000787 0.00787 NaN 4.096e-07 0
4 682.3 3.791e-07 1.483e-06 3.07e-08 0.0003151 0.003152 NaN 6.566e-07 0
8 1371 5.745e-07 1.811e-06 8.009e-09 0.0001102 0.001103 NaN 9.95e-07 0
EOD
$rackpinion_velocity_iterations << EOD
1 120.1 9.967e-08 3.934e-07 4.623e-08 0.001406 0.01406 NaN 1.726e-07 0
2 128.1 6.963e-08 2.934e-07 4.733e-08 0.000979 0.00979 NaN 1.206e-07 0
4 142.4 2.363e-07 8.783e-07 3.464e-08 0.0008912 0.008912 NaN 4.093e-07 0
8 166.7 2.22e-07 7.791e-07 2.862e-08 0.0008904 0.008905 NaN 3.845e-07 0
10 176.1 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 1
EOD
$rackpinion_position_iterations << EOD
0 103.5 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 0
1 141.9 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 0
2 176.1 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 1
EOD
$rackpinion_default << EOD
0 176.1 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 1
EOD
$rackpinion_grid << EOD
0 44.24 9.967e-08 3.934e-07 4.623e-08 0.001406 0.01406 NaN 1.726e-07 0
0 82.95 9.967e-08 3.934e-07 4.623e-08 0.001406 0.01406 NaN 1.726e-07 0
0 120.1 9.967e-08 3.934e-07 4.623e-08 0.001406 0.01406 NaN 1.726e-07 0
0 50.89 6.963e-08 2.934e-07 4.733e-08 0.000979 0.00979 NaN 1.206e-07 0
0 89.77 6.963e-08 2.934e-07 4.733e-08 0.000979 0.00979 NaN 1.206e-07 0
0 128.1 6.963e-08 2.934e-07 4.733e-08 0.000979 0.00979 NaN 1.206e-07 0
0 65.08 2.363e-07 8.783e-07 3.464e-08 0.0008912 0.008912 NaN 4.093e-07 0
0 103 2.363e-07 8.783e-07 3.464e-08 0.0008912 0.008912 NaN 4.093e-07 0
0 142.4 2.363e-07 8.783e-07 3.464e-08 0.0008912 0.008912 NaN 4.093e-07 0
0 90.88 2.22e-07 7.791e-07 2.862e-08 0.0008904 0.008905 NaN 3.845e-07 0
0 127 2.22e-07 7.791e-07 2.862e-08 0.0008904 0.008905 NaN 3.845e-07 0
0 166.7 2.22e-07 7.791e-07 2.862e-08 0.0008904 0.008905 NaN 3.845e-07 0
0 103.5 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 0
0 141.9 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 0
0 176.1 1.6e-07 6.995e-07 2.774e-08 0.000893 0.00893 NaN 2.771e-07 1
0 79.81 2.198e-07 1.111e-06 4.296e-08 0.0009532 0.009533 NaN 3.808e-07 0
0 156.1 2.198e-07 1.111e-06 4.296e-08 0.0009532 0.009533 NaN 3.808e-07 0
0 224.3 2.198e-07 1.111e-06 4.296e-08 0.0009532 0.009533 NaN 3.808e-07 0
0 91.55 1.294e-07 7.829e-07 3.873e-08 0.000899 0.00899 NaN 2.241e-07 0
0 165.3 1.294e-07 7.829e-07 3.873e-08 0.000899 0.00899 NaN 2.241e-07 0
0 239.8 1.294e-07 7.829e-07 3.873e-08 0.000899 0.00899 NaN 2.241e-07 0
0 117.7 2.125e-07 1.029e-06 2.748e-08 0.0008943 0.008943 NaN 3.681e-07 0
0 193.6 2.125e-07 1.029e-06 2.748e-08 0.0008943 0.008943 NaN 3.681e-07 0
0 265.8 2.125e-07 1.029e-06 2.748e-08 0.0008943 0.008943 NaN 3.681e-07 0
0 171.2 1.804e-07 9.29e-07 2.609e-08 0.0008972 0.008972 NaN 3.125e-07 0
0 245.5 1.804e-07 9.29e-07 2.609e-08 0.0008972 0.008972 NaN 3.125e-07 0
0 322 1.804e-07 9.29e-07 2.609e-08 0.0008972 0.008972 NaN 3.125e-07 0
0 197.6 2.365e-07 1.008e-06 2.819e-08 0.000787 0.00787 NaN 4.096e-07 0
0 271.5 2.365e-07 1.008e-06 2.819e-08 0.000787 0.00787 NaN 4.096e-07 0
0 343 2.365e-07 1.008e-06 2.819e-08 0.000787 0.00787 NaN 4.096e-07 0
0 147.9 1.758e-07 8.62e-07 3.347e-08 0.0009012 0.009013 NaN 3.044e-07 0
0 302.2 1.758e-07 8.62e-07 3.347e-08 0.0009012 0.009013 NaN 3.044e-07 0
0 446.1 1.758e-07 8.62e-07 3.347e-08 0.0009012 0.009013 NaN 3.044e-07 0
0 175.7 1.482e-07 5.777e-07 3.456e-08 0.0007948 0.007948 NaN 2.568e-07 0
0 325.7 1.482e-07 5.777e-07 3.456e-08 0.0007948 0.007948 NaN 2.568e-07 0
0 464.3 1.482e-07 5.777e-07 3.456e-08 0.0007948 0.007948 NaN 2.568e-07 0
0 226 4.262e-07 1.66e-06 3.25e-08 0.0005138 0.005138 NaN 7.382e-07 0
0 377.8 4.262e-07 1.66e-06 3.25e-08 0.0005138 0.005138 NaN 7.382e-07 0
0 527.5 4.262e-07 1.66e-06 3.25e-08 0.0005138 0.005138 NaN 7.382e-07 0
0 330 4.379e-07 2.035e-06 2.845e-08 0.0003433 0.003434 NaN 7.585e-07 0
0 482.6 4.203e-07 1.8e-06 2.845e-08 0.0003433 0.003434 NaN 7.279e-07 0
0 640.8 4.203e-07 1.8e-06 2.845e-08 0.0003433 0.003434 NaN 7.279e-07 0
0 383.3 3.791e-07 1.483e-06 3.07e-08 0.0003151 0.003152 NaN 6.566e-07 0
0 533.7 3.791e-07 1.483e-06 3.07e-08 0.0003151 0.003152 NaN 6.566e-07 0
0 682.3 3.791e-07 1.483e-06 3.07e-08 0.0003151 0.003152 NaN 6.566e-07 0
0 284.9 4.516e-07 1.414e-06 2.533e-08 0.0004324 0.004324 NaN 7.822e-07 0
0 593.1 4.516e-07 1.414e-06 2.533e-08 0.0004324 0.004324 NaN 7.822e-07 0
0 896.7 4.516e-07 1.414e-06 2.533e-08 0.0004324 0.004324 NaN 7.822e-07 0
0 349.7 8.066e-07 2.364e-06 2.836e-08 0.0002545 0.002546 NaN 1.397e-06 0
0 656.1 5.622e-07 1.724e-06 2.836e-08 0.0002545 0.002546 NaN 9.738e-07 0
0 967 5.615e-07 1.724e-06 2.836e-08 0.0002545 0.002546 NaN 9.726e-07 0
0 440.4 8.304e-07 2.587e-06 2.503e-08 0.0001602 0.001603 NaN 1.438e-06 0
0 737.1 5.959e-07 1.776e-06 2.503e-08 0.0001602 0.001603 NaN 1.032e-06 0
0 1045 5.953e-07 1.776e-06 2.503e-08 0.0001602 0.001603 NaN 1.031e-06 0
0 654.9 1.062e-06 3.154e-06 3.029e-08 0.0001173 0.001174 NaN 1.84e-06 0
0 956.5 5.559e-07 1.813e-06 3.029e-08 0.0001173 0.001174 NaN 9.628e-07 0
0 1263 5.551e-07 1.813e-06 3.029e-08 0.0001173 0.001174 NaN 9.614e-07 0
0 762.3 9.83e-07 3.092e-06 8.009e-09 0.0001102 0.001103 NaN 1.703e-06 0
0 1132 5.745e-07 1.811e-06 8.009e-09 0.0001102 0.001103 NaN 9.95e-07 0
0 1371 5.745e-07 1.811e-06 8.009e-09 0.0001102 0.001103 NaN 9.95e-07 0
EOD
set output 'rackpinion.png'
set multiplot layout 2,3 title 'rackpinion: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $rackpinion_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $rackpinion_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $rackpinion_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $rackpinion_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $rackpinion_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $rackpinion_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $rackpinion_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $rackpinion_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $rackpinion_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $rackpinion_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $rackpinion_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $rackpinion_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $rackpinion_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $rackpinion_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $rackpinion_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $rackpinion_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $rackpinion_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $rackpinion_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $rackpinion_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $rackpinion_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $rackpinion_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $rackpinion_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $rackpinion_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $rackpinion_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $rackpinion_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $rackpinion_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $rackpinion_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $rackpinion_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $rackpinion_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $rackpinion_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $rackpinion_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $rackpinion_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $rackpinion_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $rackpinion_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $rackpinion_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $rackpinion_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $rackpinion_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $rackpinion_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $rackpinion_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $rackpinion_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'coupling error RMS (rad)'
plot $rackpinion_grid using 2:9 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $rackpinion_substeps using 2:9 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $rackpinion_substeps using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $rackpinion_velocity_iterations using 2:9 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $rackpinion_velocity_iterations using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $rackpinion_position_iterations using 2:9 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $rackpinion_position_iterations using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $rackpinion_default using 2:9 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$geartrain_substeps << EOD
1 175 9.151e-08 3.574e-07 0 0 0.004982 NaN 1.585e-07 1
2 342.8 3.135e-07 1.079e-06 0 0 0.004991 NaN 5.43e-07 0
4 704.5 2.765e-07 9.12e-07 0 0 0.002547 NaN 4.79e-07 0
8 1387 3.654e-07 1.197e-06 0 0 0.001024 NaN 6.33e-07 0
EOD
$geartrain_velocity_iterations << EOD
1 115.2 5.368e-08 2.826e-07 9.934e-09 0 0.007414 NaN 9.298e-08 0
2 129.5 9.706e-08 3.971e-07 0 0 0.005274 NaN 1.681e-07 0
4 133.4 6.562e-08 2.901e-07 8.885e-09 0 0.004939 NaN 1.137e-07 0
8 167.4 1.421e-07 5.019e-07 0 0 0.004972 NaN 2.461e-07 0
10 175 9.151e-08 3.574e-07 0 0 0.004982 NaN 1.585e-07 1
EOD
$geartrain_position_iterations << EOD
0 93.57 9.151e-08 3.574e-07 0 0 0.004982 NaN 1.585e-07 0
1 140.4 9.151e-08 3.574e-07 0 0 0.004982 NaN 1.585e-07 0
2 175 9.151e-08 3.574e-07 0 0 0.004982 NaN 1.585e-07 1
EOD
$geartrain_default << EOD
0 175 9.151e-08 3.574e-07 0 0 0.004982 NaN 1.585e-07 1
EOD
$geartrain_grid << EOD
0 46.97 5.368e-08 2.826e-07 9.934e-09 0 0.007414 NaN 9.298e-08 0
0 92.47 5.368e-08 2.826e-07 9.934e-09 0 0.007414 NaN 9.298e-08 0
0 115.2 5.368e-08 2.826e-07 9.934e-09 0 0.007414 NaN 9.298e-08 0
0 50.99 9.706e-08 3.971e-07 0 0 0.005274 NaN 1.681e-07 0
0 93.86 9.706e-08 3.971e-07 0 0 0.005274 NaN 1.681e-07 0
0 129.5 9.706e-08 3.971e-07 0 0 0.005274 NaN 1.681e-07 0
0 53.31 6.562e-08 2.901e-07 8.885e-09 0 0.004939 NaN 1.137e-07 0
0 98 6.562e-08 2.901e-07 8.885e-09 0 0.004939 NaN 1.137e-07 0
0 133.4 6.562e-08 2.901e-07 8.885e-09 0 0.004939 NaN 1.137e-07 0
0 84.85 1.421e-07 5.019e-07 0 0 0.004972 NaN 2.461e-07 0
0 129.5 1.421e-07 5.019e-07 0 0 0.004972 NaN 2.461e-07 0
0 167.4 1.421e-07 5.019e-07 0 0 0.004972 NaN 2.461e-07 0
0 93.57 9.151e-08 3.574e-07 0 0 0.004982 NaN 1.585e-07 0
0 140.4 9.151e-08 3.574e-07 0 0 0.004982 NaN 1.585e-07 0
0 175 9.151e-08 3.574e-07 0 0 0.004982 NaN 1.585e-07 1
0 80.86 2.914e-07 9.392e-07 8.885e-09 0 0.005242 NaN 5.047e-07 0
0 171.9 2.914e-07 9.392e-07 8.885e-09 0 0.005242 NaN 5.047e-07 0
0 248.3 2.914e-07 9.392e-07 8.885e-09 0 0.005242 NaN 5.047e-07 0
0 91.69 2.588e-07 9.196e-07 0 0 0.004982 NaN 4.483e-07 0
0 180.5 2.588e-07 9.196e-07 0 0 0.004982 NaN 4.483e-07 0
0 261.1 2.588e-07 9.196e-07 0 0 0.004982 NaN 4.483e-07 0
0 88.8 2.811e-07 9.005e-07 0 0 0.004977 NaN 4.868e-07 0
0 176 2.811e-07 9.005e-07 0 0 0.004977 NaN 4.868e-07 0
0 248.8 2.811e-07 9.005e-07 0 0 0.004977 NaN 4.868e-07 0
0 158.1 3.574e-07 1.147e-06 0 0 0.00499 NaN 6.191e-07 0
0 250 3.574e-07 1.147e-06 0 0 0.00499 NaN 6.191e-07 0
0 317.8 3.574e-07 1.147e-06 0 0 0.00499 NaN 6.191e-07 0
0 179.6 3.135e-07 1.079e-06 0 0 0.004991 NaN 5.43e-07 0
0 272.6 3.135e-07 1.079e-06 0 0 0.004991 NaN 5.43e-07 0
0 342.8 3.135e-07 1.079e-06 0 0 0.004991 NaN 5.43e-07 0
0 155.9 2.781e-07 1.026e-06 0 0 0.004991 NaN 4.817e-07 0
0 332.3 2.781e-07 1.026e-06 0 0 0.004991 NaN 4.817e-07 0
0 478.1 2.781e-07 1.026e-06 0 0 0.004991 NaN 4.817e-07 0
0 172.6 2.189e-07 8.091e-07 0 0 0.004995 NaN 3.792e-07 0
0 372.6 2.189e-07 8.091e-07 0 0 0.004995 NaN 3.792e-07 0
0 531.3 2.189e-07 8.091e-07 0 0 0.004995 NaN 3.792e-07 0
0 166.8 2.984e-07 1.095e-06 0 0 0.003871 NaN 5.169e-07 0
0 341.9 2.984e-07 1.095e-06 0 0 0.003871 NaN 5.169e-07 0
0 518.3 2.984e-07 1.095e-06 0 0 0.003871 NaN 5.169e-07 0
0 310.2 9.714e-08 5.018e-07 0 0 0.00268 NaN 1.683e-07 0
0 493 9.714e-08 5.018e-07 0 0 0.00268 NaN 1.683e-07 0
0 625.7 9.714e-08 5.018e-07 0 0 0.00268 NaN 1.683e-07 0
0 352.2 2.765e-07 9.12e-07 0 0 0.002547 NaN 4.79e-07 0
0 539 2.765e-07 9.12e-07 0 0 0.002547 NaN 4.79e-07 0
0 704.5 2.765e-07 9.12e-07 0 0 0.002547 NaN 4.79e-07 0
0 303.5 3.504e-07 1.381e-06 0 0 0.003795 NaN 6.069e-07 0
0 661.4 3.504e-07 1.381e-06 0 0 0.003795 NaN 6.069e-07 0
0 983.1 3.504e-07 1.381e-06 0 0 0.003795 NaN 6.069e-07 0
0 307.3 3.373e-07 1.054e-06 0 0 0.002157 NaN 5.842e-07 0
0 666.8 3.373e-07 1.054e-06 0 0 0.002157 NaN 5.842e-07 0
0 998 3.373e-07 1.054e-06 0 0 0.002157 NaN 5.842e-07 0
0 412.5 6.079e-07 2.063e-06 0 0 0.001355 NaN 1.053e-06 0
0 772.8 6.079e-07 2.063e-06 0 0 0.001355 NaN 1.053e-06 0
0 1128 6.079e-07 2.063e-06 0 0 0.001355 NaN 1.053e-06 0
0 605.2 1.096e-07 5.447e-07 0 0 0.001057 NaN 1.899e-07 0
0 973.3 1.096e-07 5.447e-07 0 0 0.001057 NaN 1.899e-07 0
0 1255 1.096e-07 5.447e-07 0 0 0.001057 NaN 1.899e-07 0
0 687.5 3.654e-07 1.197e-06 0 0 0.001024 NaN 6.33e-07 0
0 1067 3.654e-07 1.197e-06 0 0 0.001024 NaN 6.33e-07 0
0 1387 3.654e-07 1.197e-06 0 0 0.001024 NaN 6.33e-07 0
EOD
set output 'geartrain.png'
set multiplot layout 2,3 title 'geartrain: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $geartrain_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $geartrain_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $geartrain_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $geartrain_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $geartrain_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $geartrain_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $geartrain_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $geartrain_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $geartrain_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $geartrain_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $geartrain_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $geartrain_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $geartrain_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $geartrain_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $geartrain_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $geartrain_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $geartrain_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $geartrain_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $geartrain_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $geartrain_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $geartrain_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $geartrain_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $geartrain_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $geartrain_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $geartrain_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $geartrain_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $geartrain_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $geartrain_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $geartrain_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $geartrain_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $geartrain_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $geartrain_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'coupling error RMS (rad)'
plot $geartrain_grid using 2:9 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $geartrain_substeps using 2:9 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $geartrain_substeps using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $geartrain_velocity_iterations using 2:9 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $geartrain_velocity_iterations using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $geartrain_position_iterations using 2:9 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $geartrain_position_iterations using 2:9:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $geartrain_default using 2:9 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
$ragdoll_substeps << EOD
1 1198 0.001148 0.0243 0.01064 0.01626 0.1348 NaN NaN 1
2 2547 0.0004763 0.0135 0.005732 0.008569 0.07411 NaN NaN 0
4 4720 0.0002185 0.005003 0.00299 0.004719 0.06051 NaN NaN 0
8 9126 7.544e-05 0.003406 0.001575 0.004663 0.04278 NaN NaN 0
EOD
$ragdoll_velocity_iterations << EOD
1 854.3 0.003339 0.03679 0.0846 0.015 0.1254 NaN NaN 0
2 797.5 0.002105 0.03833 0.03552 0.01461 0.1247 NaN NaN 0
4 902.5 0.001538 0.02703 0.01408 0.01453 0.1276 NaN NaN 0
8 1097 0.001344 0.03081 0.01072 0.01608 0.135 NaN NaN 0
10 1198 0.001148 0.0243 0.01064 0.01626 0.1348 NaN NaN 1
EOD
$ragdoll_position_iterations << EOD
0 752.6 0.003771 0.03379 0.01071 0.0184 0.1372 NaN NaN 0
1 1031 0.001481 0.02674 0.01066 0.01634 0.1265 NaN NaN 0
2 1198 0.001148 0.0243 0.01064 0.01626 0.1348 NaN NaN 1
EOD
$ragdoll_default << EOD
0 1198 0.001148 0.0243 0.01064 0.01626 0.1348 NaN NaN 1
EOD
$ragdoll_grid << EOD
0 314.4 0.007678 0.09583 0.08473 0.01613 0.1296 NaN NaN 0
0 531.2 0.004215 0.05928 0.08484 0.01533 0.1299 NaN NaN 0
0 854.3 0.003339 0.03679 0.0846 0.015 0.1254 NaN NaN 0
0 376.2 0.004924 0.05746 0.03554 0.01698 0.131 NaN NaN 0
0 580.7 0.002786 0.04212 0.03559 0.01494 0.1202 NaN NaN 0
0 797.5 0.002105 0.03833 0.03552 0.01461 0.1247 NaN NaN 0
0 461.7 0.004032 0.05228 0.01413 0.01682 0.123 NaN NaN 0
0 683 0.001928 0.02965 0.01411 0.01525 0.1302 NaN NaN 0
0 902.5 0.001538 0.02703 0.01408 0.01453 0.1276 NaN NaN 0
0 658.9 0.003917 0.03499 0.01078 0.01773 0.1273 NaN NaN 0
0 880.7 0.001635 0.03444 0.01073 0.01613 0.1351 NaN NaN 0
0 1097 0.001344 0.03081 0.01072 0.01608 0.135 NaN NaN 0
0 752.6 0.003771 0.03379 0.01071 0.0184 0.1372 NaN NaN 0
0 1031 0.001481 0.02674 0.01066 0.01634 0.1265 NaN NaN 0
0 1198 0.001148 0.0243 0.01064 0.01626 0.1348 NaN NaN 1
0 559.8 0.002864 0.05885 0.03999 0.01011 0.07627 NaN NaN 0
0 1071 0.001657 0.04133 0.03975 0.01202 0.08953 NaN NaN 0
0 1447 0.001375 0.03465 0.03971 0.01233 0.09322 NaN NaN 0
0 661.3 0.002063 0.0334 0.01081 0.009192 0.07932 NaN NaN 0
0 1145 0.001111 0.03401 0.01083 0.008315 0.07905 NaN NaN 0
0 1703 0.0008666 0.01924 0.0108 0.008811 0.08404 NaN NaN 0
0 924.7 0.001702 0.02772 0.006353 0.009466 0.08578 NaN NaN 0
0 1391 0.000761 0.01692 0.00641 0.008298 0.07369 NaN NaN 0
0 1908 0.0006221 0.02068 0.006349 0.008823 0.08858 NaN NaN 0
0 1309 0.001568 0.03055 0.005831 0.008603 0.06827 NaN NaN 0
0 1699 0.0006517 0.01698 0.005784 0.008427 0.07115 NaN NaN 0
0 2276 0.0004944 0.01348 0.005763 0.008398 0.0735 NaN NaN 0
0 1483 0.001593 0.02519 0.00572 0.008722 0.07006 NaN NaN 0
0 2137 0.0006255 0.017 0.005726 0.008447 0.07193 NaN NaN 0
0 2547 0.0004763 0.0135 0.005732 0.008569 0.07411 NaN NaN 0
0 1120 0.001292 0.03908 0.01077 0.01078 0.08187 NaN NaN 0
0 2117 0.0007391 0.02659 0.01005 0.01013 0.08163 NaN NaN 0
0 2828 0.0005982 0.01774 0.009828 0.01026 0.08315 NaN NaN 0
0 1217 0.000945 0.02531 0.005976 0.008367 0.07311 NaN NaN 0
0 2064 0.0004699 0.01359 0.005478 0.00747 0.06723 NaN NaN 0
0 2991 0.0004085 0.01418 0.00567 0.007494 0.06762 NaN NaN 0
0 1631 0.0008188 0.01272 0.003975 0.007095 0.06983 NaN NaN 0
0 2686 0.0003434 0.007338 0.003819 0.005484 0.063 NaN NaN 0
0 3615 0.0002905 0.006749 0.003782 0.005543 0.06472 NaN NaN 0
0 2670 0.0008016 0.01096 0.003096 0.006509 0.06609 NaN NaN 0
0 3585 0.0002783 0.006197 0.003057 0.005002 0.06245 NaN NaN 0
0 4428 0.0002085 0.005057 0.003059 0.005092 0.06081 NaN NaN 0
0 2860 0.000782 0.0121 0.003035 0.005699 0.04566 NaN NaN 0
0 3956 0.0002767 0.006198 0.002999 0.005105 0.06421 NaN NaN 0
0 4720 0.0002185 0.005003 0.00299 0.004719 0.06051 NaN NaN 0
0 2190 0.0005321 0.01484 0.005001 0.01252 0.09516 NaN NaN 0
0 3974 0.0002881 0.01328 0.00518 0.01296 0.09608 NaN NaN 0
0 5679 0.0002398 0.01146 0.005104 0.013 0.09727 NaN NaN 0
0 2503 0.0004367 0.01241 0.003365 0.008457 0.07345 NaN NaN 0
0 4335 0.0001639 0.006571 0.00301 0.009098 0.07663 NaN NaN 0
0 5959 0.0001504 0.005955 0.003066 0.009109 0.07672 NaN NaN 0
0 3305 0.0003917 0.008346 0.002256 0.0061 0.0632 NaN NaN 0
0 5072 0.0001133 0.00539 0.002364 0.00708 0.06993 NaN NaN 0
0 6826 0.0001009 0.0046 0.002385 0.007028 0.06833 NaN NaN 0
0 4948 0.0003691 0.004163 0.001621 0.005286 0.06579 NaN NaN 0
0 6706 9.131e-05 0.003105 0.001657 0.004878 0.04343 NaN NaN 0
0 8452 7.165e-05 0.00263 0.001664 0.004856 0.04377 NaN NaN 0
0 5647 0.0003685 0.004038 0.001552 0.002985 0.03389 NaN NaN 0
0 7506 0.0001024 0.003863 0.001591 0.00466 0.04269 NaN NaN 0
0 9126 7.544e-05 0.003406 0.001575 0.004663 0.04278 NaN NaN 0
EOD
set output 'ragdoll.png'
set multiplot layout 2,3 title 'ragdoll: error against cost, one knob varied at a time from the default (labels: its value)'
set title 'position error RMS (m, rad)'
plot $ragdoll_grid using 2:3 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $ragdoll_substeps using 2:3 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $ragdoll_substeps using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $ragdoll_velocity_iterations using 2:3 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $ragdoll_velocity_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $ragdoll_position_iterations using 2:3 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $ragdoll_position_iterations using 2:3:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $ragdoll_default using 2:3 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'position error max (m, rad)'
plot $ragdoll_grid using 2:4 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $ragdoll_substeps using 2:4 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $ragdoll_substeps using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $ragdoll_velocity_iterations using 2:4 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $ragdoll_velocity_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $ragdoll_position_iterations using 2:4 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $ragdoll_position_iterations using 2:4:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $ragdoll_default using 2:4 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'velocity residual |Jv| RMS (m/s, rad/s)'
plot $ragdoll_grid using 2:5 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $ragdoll_substeps using 2:5 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $ragdoll_substeps using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $ragdoll_velocity_iterations using 2:5 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $ragdoll_velocity_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $ragdoll_position_iterations using 2:5 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $ragdoll_position_iterations using 2:5:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $ragdoll_default using 2:5 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (m)'
plot $ragdoll_grid using 2:6 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $ragdoll_substeps using 2:6 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $ragdoll_substeps using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $ragdoll_velocity_iterations using 2:6 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $ragdoll_velocity_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $ragdoll_position_iterations using 2:6 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $ragdoll_position_iterations using 2:6:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $ragdoll_default using 2:6 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
set title 'trajectory error RMS (rad)'
plot $ragdoll_grid using 2:7 with points pt 7 ps 0.4 lc rgb '#bbbbbb' title 'every combination', $ragdoll_substeps using 2:7 with linespoints pt 7 lc rgb '#1f77b4' title 'substeps', $ragdoll_substeps using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#1f77b4' notitle, $ragdoll_velocity_iterations using 2:7 with linespoints pt 7 lc rgb '#d62728' title 'velocity iterations', $ragdoll_velocity_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#d62728' notitle, $ragdoll_position_iterations using 2:7 with linespoints pt 7 lc rgb '#2ca02c' title 'position iterations', $ragdoll_position_iterations using 2:7:($10 > 0 ? '' : sprintf('%d', $1)) with labels offset char 0.8,0.6 tc rgb '#2ca02c' notitle, $ragdoll_default using 2:7 with points pt 7 ps 1.5 lc rgb 'black' title 'default 1 / 10 / 2'
unset multiplot
