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
2014 2.01191e+09 2.1527e+08 NaN
2016 3.58414e+09 3.07529e+08 NaN
2018 6.71804e+10 4.30541e+08 8e+09
2020 1.10047e+11 7.30382e+08 1.33672e+10
2022 1.80174e+11 6.88865e+08 2.59738e+10
2025 2.08044e+11 9.22588e+08 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.44561e+09 3.23386e+08 NaN
2017 4.58058e+09 4.65138e+08 NaN
2018 8.97275e+10 5.91994e+08 1e+10
2020 1.31539e+11 8.99523e+08 1.59024e+10
2022 3.05269e+11 9.68717e+08 4.40196e+10
2025 3.87255e+11 1.72216e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_naive.png'
set title "sphere-1m, naive: rays/s that 1080p60 needs against each GPU's limits (3.50 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.957e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 6.78e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 1.8491e+09 2.10144e+08 NaN
2016 3.29409e+09 3.00206e+08 NaN
2018 4.40342e+10 4.20288e+08 8e+09
2020 6.5094e+10 7.12988e+08 1.33672e+10
2022 1.06576e+11 6.7246e+08 2.59738e+10
2025 1.49685e+11 9.00617e+08 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.2477e+09 3.15685e+08 NaN
2017 4.20989e+09 4.54061e+08 NaN
2018 5.8813e+10 5.77896e+08 1e+10
2020 7.78072e+10 8.78101e+08 1.59024e+10
2022 1.8057e+11 9.45647e+08 4.40196e+10
2025 2.78625e+11 1.68115e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_bsdf.png'
set title "sphere-1m, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.50 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.79174e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 4.12e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 1.75229e+09 2.05918e+08 NaN
2016 3.12163e+09 2.94168e+08 NaN
2018 3.5394e+10 4.11836e+08 8e+09
2020 5.23215e+10 6.9865e+08 1.33672e+10
2022 8.56637e+10 6.58937e+08 2.59738e+10
2025 1.25262e+11 8.82505e+08 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.13002e+09 3.09336e+08 NaN
2017 3.98948e+09 4.4493e+08 NaN
2018 4.7273e+10 5.66274e+08 1e+10
2020 6.25402e+10 8.60443e+08 1.59024e+10
2022 1.4514e+11 9.2663e+08 4.40196e+10
2025 2.33164e+11 1.64734e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_nee.png'
set title "sphere-1m, nee: rays/s that 1080p60 needs against each GPU's limits (5.57 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.87668e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 271 spp', \
     4.15992e+10 with lines lc 'black' dt 4 lw 2 title 'need: bilateral, 60.1 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 1.68098e+09 1.9838e+08 NaN
2016 2.9946e+09 2.834e+08 NaN
2018 4.17924e+10 3.9676e+08 8e+09
2020 6.17801e+10 6.73075e+08 1.33672e+10
2022 1.0115e+11 6.34816e+08 2.59738e+10
2025 1.48563e+11 8.50199e+08 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 2.04334e+09 2.98013e+08 NaN
2017 3.82714e+09 4.28642e+08 NaN
2018 5.58189e+10 5.45545e+08 1e+10
2020 7.3846e+10 8.28945e+08 1.59024e+10
2022 1.71378e+11 8.92709e+08 4.40196e+10
2025 2.76537e+11 1.58704e+09 7.32891e+10
EOD
set output 'sphere-1m_roofline_bdpt.png'
set title "sphere-1m, bdpt: rays/s that 1080p60 needs against each GPU's limits (11.13 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.71098e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 124 spp', \
     4.50761e+10 with lines lc 'black' dt 4 lw 2 title 'need: bilateral, 32.6 spp', \
     4.54541e+10 with lines lc 'black' dt 5 lw 2 title 'need: atrous, 32.8 spp'
