# Written by `fragpath study` (src/study/roofline_plot.cpp); edit and rerun with
#   gnuplot environment_roofline.gp
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
2014 3.40735e+09 4.45391e+08 NaN
2016 6.07004e+09 6.36273e+08 NaN
2018 1.0893e+11 8.90783e+08 8e+09
2020 1.88095e+11 1.51115e+09 1.33672e+10
2022 3.0796e+11 1.42525e+09 2.59738e+10
2025 3.55595e+11 1.90882e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.14185e+09 6.69081e+08 NaN
2017 7.75761e+09 9.62363e+08 NaN
2018 1.45489e+11 1.22483e+09 1e+10
2020 2.24831e+11 1.8611e+09 1.59024e+10
2022 5.21775e+11 2.00426e+09 4.40196e+10
2025 6.61908e+11 3.56313e+09 7.32891e+10
EOD
set output 'environment_roofline_naive.png'
set title "environment, naive: rays/s that 1080p60 needs against each GPU's limits (1.82 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     6.63585e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 2.93e+05 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.42419e+09 4.68715e+08 NaN
2016 6.10004e+09 6.69592e+08 NaN
2018 8.11822e+10 9.37429e+08 8e+09
2020 1.20008e+11 1.59028e+09 1.33672e+10
2022 1.96484e+11 1.49989e+09 2.59738e+10
2025 2.62153e+11 2.00878e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.16232e+09 7.04118e+08 NaN
2017 7.79594e+09 1.01276e+09 NaN
2018 1.08429e+11 1.28897e+09 1e+10
2020 1.43447e+11 1.95856e+09 1.59024e+10
2022 3.32903e+11 2.10922e+09 4.40196e+10
2025 4.87975e+11 3.74972e+09 7.32891e+10
EOD
set output 'environment_roofline_bsdf.png'
set title "environment, bsdf: rays/s that 1080p60 needs against each GPU's limits (1.81 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.31449e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.92e+05 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.21457e+09 4.51506e+08 NaN
2016 5.72661e+09 6.45009e+08 NaN
2018 5.43042e+10 9.03012e+08 8e+09
2020 8.02758e+10 1.5319e+09 1.33672e+10
2022 1.31432e+11 1.44482e+09 2.59738e+10
2025 1.86327e+11 1.93503e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.90751e+09 6.78267e+08 NaN
2017 7.3187e+09 9.75576e+08 NaN
2018 7.25299e+10 1.24164e+09 1e+10
2020 9.5954e+10 1.88665e+09 1.59024e+10
2022 2.22684e+11 2.03178e+09 4.40196e+10
2025 3.46832e+11 3.61205e+09 7.32891e+10
EOD
set output 'environment_roofline_nee.png'
set title "environment, nee: rays/s that 1080p60 needs against each GPU's limits (2.37 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.94729e+10 with lines lc 'black' dt 3 lw 2 title 'need: none, 168 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.04237e+09 4.28712e+08 NaN
2016 5.41984e+09 6.12446e+08 NaN
2018 4.12869e+10 8.57424e+08 8e+09
2020 6.10329e+10 1.45456e+09 1.33672e+10
2022 9.99264e+10 1.37188e+09 2.59738e+10
2025 1.41675e+11 1.83734e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.69819e+09 6.44025e+08 NaN
2017 6.92664e+09 9.26324e+08 NaN
2018 5.51437e+10 1.17896e+09 1e+10
2020 7.29529e+10 1.7914e+09 1.59024e+10
2022 1.69305e+11 1.9292e+09 4.40196e+10
2025 2.63715e+11 3.4297e+09 7.32891e+10
EOD
set output 'environment_roofline_bdpt.png'
set title "environment, bdpt: rays/s that 1080p60 needs against each GPU's limits (1.81 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.31449e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.92e+05 spp'
