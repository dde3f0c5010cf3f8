# Written by `fragpath study` (src/study/roofline_plot.cpp); edit and rerun with
#   gnuplot cornell_roofline.gp
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
2014 3.47021e+09 3.04061e+08 NaN
2016 6.18202e+09 4.34372e+08 NaN
2018 6.8285e+10 6.08121e+08 8e+09
2020 1.12042e+11 1.03163e+09 1.33672e+10
2022 1.83441e+11 9.72994e+08 2.59738e+10
2025 2.11815e+11 1.30312e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.21826e+09 4.56769e+08 NaN
2017 7.90071e+09 6.56988e+08 NaN
2018 9.1203e+10 8.36166e+08 1e+10
2020 1.33924e+11 1.27054e+09 1.59024e+10
2022 3.10803e+11 1.36827e+09 4.40196e+10
2025 3.94275e+11 2.43248e+09 7.32891e+10
EOD
set output 'cornell_roofline_naive.png'
set title "cornell, naive: rays/s that 1080p60 needs against each GPU's limits (3.33 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     2.99737e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 7.23e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.17442e+09 2.97306e+08 NaN
2016 5.65509e+09 4.24723e+08 NaN
2018 4.50938e+10 5.94613e+08 8e+09
2020 6.66604e+10 1.00872e+09 1.33672e+10
2022 1.0914e+11 9.51381e+08 2.59738e+10
2025 1.53027e+11 1.27417e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.85871e+09 4.46623e+08 NaN
2017 7.22729e+09 6.42394e+08 NaN
2018 6.02282e+10 8.17593e+08 1e+10
2020 7.96794e+10 1.24232e+09 1.59024e+10
2022 1.84915e+11 1.33788e+09 4.40196e+10
2025 2.84845e+11 2.37845e+09 7.32891e+10
EOD
set output 'cornell_roofline_bsdf.png'
set title "cornell, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.31 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.63251e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 3.97e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.07796e+09 3.02554e+08 NaN
2016 5.48325e+09 4.3222e+08 NaN
2018 3.59256e+10 6.05108e+08 8e+09
2020 5.31073e+10 1.02652e+09 1.33672e+10
2022 8.69503e+10 9.68172e+08 2.59738e+10
2025 1.27025e+11 1.29666e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.74145e+09 4.54506e+08 NaN
2017 7.00767e+09 6.53732e+08 NaN
2018 4.7983e+10 8.32023e+08 1e+10
2020 6.34794e+10 1.26424e+09 1.59024e+10
2022 1.47319e+11 1.36149e+09 4.40196e+10
2025 2.36446e+11 2.42043e+09 7.32891e+10
EOD
set output 'cornell_roofline_nee.png'
set title "cornell, nee: rays/s that 1080p60 needs against each GPU's limits (5.20 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.42179e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 220 spp', \
     3.69657e+10 with lines lc 'black' dt 4 lw 2 title 'need: atrous, 57.1 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.1182e+09 2.99341e+08 NaN
2016 5.55493e+09 4.2763e+08 NaN
2018 4.22345e+10 5.98681e+08 8e+09
2020 6.24336e+10 1.01562e+09 1.33672e+10
2022 1.0222e+11 9.5789e+08 2.59738e+10
2025 1.50091e+11 1.28289e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.79037e+09 4.49679e+08 NaN
2017 7.09929e+09 6.4679e+08 NaN
2018 5.64093e+10 8.23187e+08 1e+10
2020 7.46272e+10 1.25082e+09 1.59024e+10
2022 1.7319e+11 1.34703e+09 4.40196e+10
2025 2.79381e+11 2.39473e+09 7.32891e+10
EOD
set output 'cornell_roofline_bdpt.png'
set title "cornell, bdpt: rays/s that 1080p60 needs against each GPU's limits (10.76 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.52332e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 114 spp', \
     3.75074e+10 with lines lc 'black' dt 4 lw 2 title 'need: atrous, 28 spp'
