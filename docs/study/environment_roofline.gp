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
2014 3.40309e+09 4.44648e+08 NaN
2016 6.06246e+09 6.35211e+08 NaN
2018 1.08887e+11 8.89296e+08 8e+09
2020 1.87992e+11 1.50863e+09 1.33672e+10
2022 3.07791e+11 1.42287e+09 2.59738e+10
2025 3.554e+11 1.90563e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.13667e+09 6.67964e+08 NaN
2017 7.74791e+09 9.60757e+08 NaN
2018 1.45432e+11 1.22278e+09 1e+10
2020 2.24708e+11 1.85799e+09 1.59024e+10
2022 5.21489e+11 2.00092e+09 4.40196e+10
2025 6.61545e+11 3.55718e+09 7.32891e+10
EOD
set output 'environment_roofline_naive.png'
set title "environment, naive: rays/s that 1080p60 needs against each GPU's limits (1.82 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     7.44753e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 3.29e+05 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.43346e+09 4.69909e+08 NaN
2016 6.11655e+09 6.71299e+08 NaN
2018 8.15629e+10 9.39818e+08 8e+09
2020 1.20571e+11 1.59433e+09 1.33672e+10
2022 1.97406e+11 1.50371e+09 2.59738e+10
2025 2.63266e+11 2.0139e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.17359e+09 7.05912e+08 NaN
2017 7.81705e+09 1.01534e+09 NaN
2018 1.08937e+11 1.29225e+09 1e+10
2020 1.44119e+11 1.96355e+09 1.59024e+10
2022 3.34464e+11 2.11459e+09 4.40196e+10
2025 4.90046e+11 3.75927e+09 7.32891e+10
EOD
set output 'environment_roofline_bsdf.png'
set title "environment, bsdf: rays/s that 1080p60 needs against each GPU's limits (1.81 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.10679e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.83e+05 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.22227e+09 4.53044e+08 NaN
2016 5.74032e+09 6.47206e+08 NaN
2018 5.42697e+10 9.06088e+08 8e+09
2020 8.02247e+10 1.53711e+09 1.33672e+10
2022 1.31348e+11 1.44974e+09 2.59738e+10
2025 1.86212e+11 1.94162e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.91687e+09 6.80577e+08 NaN
2017 7.33622e+09 9.78899e+08 NaN
2018 7.24837e+10 1.24587e+09 1e+10
2020 9.5893e+10 1.89308e+09 1.59024e+10
2022 2.22543e+11 2.0387e+09 4.40196e+10
2025 3.46617e+11 3.62435e+09 7.32891e+10
EOD
set output 'environment_roofline_nee.png'
set title "environment, nee: rays/s that 1080p60 needs against each GPU's limits (2.37 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.9009e+10 with lines lc 'black' dt 3 lw 2 title 'need: none, 166 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.05128e+09 4.29883e+08 NaN
2016 5.43571e+09 6.14118e+08 NaN
2018 4.14806e+10 8.59765e+08 8e+09
2020 6.13191e+10 1.45853e+09 1.33672e+10
2022 1.00395e+11 1.37562e+09 2.59738e+10
2025 1.42305e+11 1.84235e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.70902e+09 6.45783e+08 NaN
2017 6.94692e+09 9.28853e+08 NaN
2018 5.54024e+10 1.18218e+09 1e+10
2020 7.3295e+10 1.7963e+09 1.59024e+10
2022 1.70099e+11 1.93447e+09 4.40196e+10
2025 2.64888e+11 3.43906e+09 7.32891e+10
EOD
set output 'environment_roofline_bdpt.png'
set title "environment, bdpt: rays/s that 1080p60 needs against each GPU's limits (1.81 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     4.10679e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 1.83e+05 spp'
