# Written by `fragpath study` (src/study/roofline_plot.cpp); edit and rerun with
#   gnuplot sphere-1m_roofline.gp
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
2014 2.01197e+09 2.15255e+08 NaN
2016 3.58423e+09 3.07508e+08 NaN
2018 6.71906e+10 4.30511e+08 8e+09
2020 1.10064e+11 7.30331e+08 1.33672e+10
2022 1.80203e+11 6.88817e+08 2.59738e+10
2025 2.08077e+11 9.22523e+08 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.44567e+09 3.23364e+08 NaN
2017 4.5807e+09 4.65106e+08 NaN
2018 8.97412e+10 5.91952e+08 1e+10
2020 1.3156e+11 8.9946e+08 1.59024e+10
2022 3.05317e+11 9.6865e+08 4.40196e+10
2025 3.87316e+11 1.72204e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_naive.png'
set title "sphere-1m, naive: rays/s that 1080p60 needs against each GPU's limits (3.50 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.96417e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 6.8e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 1.84856e+09 2.10096e+08 NaN
2016 3.29313e+09 3.00138e+08 NaN
2018 4.403e+10 4.20193e+08 8e+09
2020 6.50878e+10 7.12827e+08 1.33672e+10
2022 1.06565e+11 6.72309e+08 2.59738e+10
2025 1.49671e+11 9.00413e+08 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.24704e+09 3.15614e+08 NaN
2017 4.20867e+09 4.53958e+08 NaN
2018 5.88074e+10 5.77765e+08 1e+10
2020 7.77997e+10 8.77903e+08 1.59024e+10
2022 1.80553e+11 9.45434e+08 4.40196e+10
2025 2.78598e+11 1.68077e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_bsdf.png'
set title "sphere-1m, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.50 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.83548e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 4.22e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 1.75228e+09 2.05923e+08 NaN
2016 3.12161e+09 2.94176e+08 NaN
2018 3.53714e+10 4.11847e+08 8e+09
2020 5.22882e+10 6.98669e+08 1.33672e+10
2022 8.56091e+10 6.58955e+08 2.59738e+10
2025 1.25185e+11 8.82529e+08 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.13001e+09 3.09345e+08 NaN
2017 3.98946e+09 4.44942e+08 NaN
2018 4.72428e+10 5.66289e+08 1e+10
2020 6.25003e+10 8.60466e+08 1.59024e+10
2022 1.45047e+11 9.26655e+08 4.40196e+10
2025 2.3302e+11 1.64739e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_nee.png'
set title "sphere-1m, nee: rays/s that 1080p60 needs against each GPU's limits (5.57 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.8952e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 273 spp', \
     3.95009e+10 with lines lc 'black' dt 4 lw 2 title 'need: bilateral, 57 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 1.68102e+09 1.98387e+08 NaN
2016 2.99466e+09 2.8341e+08 NaN
2018 4.17722e+10 3.96774e+08 8e+09
2020 6.17502e+10 6.73098e+08 1.33672e+10
2022 1.01101e+11 6.34838e+08 2.59738e+10
2025 1.48492e+11 8.50229e+08 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.04339e+09 2.98023e+08 NaN
2017 3.82722e+09 4.28657e+08 NaN
2018 5.57918e+10 5.45564e+08 1e+10
2020 7.38103e+10 8.28973e+08 1.59024e+10
2022 1.71295e+11 8.92741e+08 4.40196e+10
2025 2.76405e+11 1.58709e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_bdpt.png'
set title "sphere-1m, bdpt: rays/s that 1080p60 needs against each GPU's limits (11.13 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.70907e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 123 spp', \
     4.41597e+10 with lines lc 'black' dt 4 lw 2 title 'need: bilateral, 31.9 spp', \
     4.51197e+10 with lines lc 'black' dt 5 lw 2 title 'need: atrous, 32.6 spp'
