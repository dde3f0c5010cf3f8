# Written by `fragpath study` (src/study/roofline_plot.cpp); edit and rerun with
#   gnuplot cornell-checker_roofline.gp
set terminal pngcairo size 900,560 font 'sans,10'
set grid
set key outside right top
set logscale y
set format y '10^{%T}'
set xlabel 'year'
set ylabel 'rays per second'
set xrange [2013.5:2025.5]

$naive_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.47314e+09 3.0437e+08 NaN
2016 6.18724e+09 4.34814e+08 NaN
2018 6.8271e+10 6.08739e+08 8e+09
2020 1.1204e+11 1.03268e+09 1.33672e+10
2022 1.83438e+11 9.73982e+08 2.59738e+10
2025 2.11812e+11 1.30444e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.22182e+09 4.57234e+08 NaN
2017 7.90739e+09 6.57656e+08 NaN
2018 9.11842e+10 8.37016e+08 1e+10
2020 1.33922e+11 1.27183e+09 1.59024e+10
2022 3.10798e+11 1.36966e+09 4.40196e+10
2025 3.9427e+11 2.43496e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_naive.png'
set title "cornell-checker, naive: rays/s that 1080p60 needs against each GPU's limits (3.31 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.53364e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 6.15e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.17663e+09 2.97555e+08 NaN
2016 5.65902e+09 4.25079e+08 NaN
2018 4.51121e+10 5.95111e+08 8e+09
2020 6.66874e+10 1.00956e+09 1.33672e+10
2022 1.09184e+11 9.52177e+08 2.59738e+10
2025 1.53058e+11 1.27524e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.86139e+09 4.46997e+08 NaN
2017 7.23232e+09 6.42932e+08 NaN
2018 6.02527e+10 8.18277e+08 1e+10
2020 7.97118e+10 1.24336e+09 1.59024e+10
2022 1.8499e+11 1.339e+09 4.40196e+10
2025 2.84903e+11 2.38044e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_bsdf.png'
set title "cornell-checker, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.28 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.46781e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 3.6e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.08046e+09 3.02829e+08 NaN
2016 5.48771e+09 4.32613e+08 NaN
2018 3.59739e+10 6.05658e+08 8e+09
2020 5.31789e+10 1.02746e+09 1.33672e+10
2022 8.70673e+10 9.69053e+08 2.59738e+10
2025 1.27184e+11 1.29784e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.7445e+09 4.5492e+08 NaN
2017 7.01337e+09 6.54327e+08 NaN
2018 4.80476e+10 8.3278e+08 1e+10
2020 6.35649e+10 1.26539e+09 1.59024e+10
2022 1.47518e+11 1.36273e+09 4.40196e+10
2025 2.36741e+11 2.42263e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_nee.png'
set title "cornell-checker, nee: rays/s that 1080p60 needs against each GPU's limits (5.17 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.41019e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 219 spp', \
     3.44582e+10 with lines lc 'black' dt 4 lw 2 title 'need: atrous, 53.6 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.11957e+09 2.9946e+08 NaN
2016 5.55738e+09 4.278e+08 NaN
2018 4.22914e+10 5.9892e+08 8e+09
2020 6.25177e+10 1.01602e+09 1.33672e+10
2022 1.02357e+11 9.58272e+08 2.59738e+10
2025 1.50289e+11 1.2834e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.79204e+09 4.49858e+08 NaN
2017 7.10241e+09 6.47047e+08 NaN
2018 5.64853e+10 8.23515e+08 1e+10
2020 7.47277e+10 1.25131e+09 1.59024e+10
2022 1.73424e+11 1.34757e+09 4.40196e+10
2025 2.79749e+11 2.39568e+09 7.32891e+10
EOD
set output 'cornell-checker_roofline_bdpt.png'
set title "cornell-checker, bdpt: rays/s that 1080p60 needs against each GPU's limits (10.72 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.44688e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 108 spp', \
     3.24882e+10 with lines lc 'black' dt 4 lw 2 title 'need: atrous, 24.4 spp'
