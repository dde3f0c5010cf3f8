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
2014 3.4698e+09 3.04011e+08 NaN
2016 6.1813e+09 4.34301e+08 NaN
2018 6.82786e+10 6.08021e+08 8e+09
2020 1.12029e+11 1.03146e+09 1.33672e+10
2022 1.8342e+11 9.72834e+08 2.59738e+10
2025 2.11791e+11 1.3029e+09 3.94102e+10
EOD
$naive_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 4.21777e+09 4.56695e+08 NaN
2017 7.8998e+09 6.5688e+08 NaN
2018 9.11944e+10 8.36029e+08 1e+10
2020 1.33909e+11 1.27033e+09 1.59024e+10
2022 3.10768e+11 1.36805e+09 4.40196e+10
2025 3.94231e+11 2.43209e+09 7.32891e+10
EOD
set output 'cornell_roofline_naive.png'
set title "cornell, naive: rays/s that 1080p60 needs against each GPU's limits (3.34 rays per path)"
plot $naive_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $naive_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $naive_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $naive_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $naive_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $naive_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     3.02167e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 7.28e+04 spp'

$bsdf_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.17349e+09 2.972e+08 NaN
2016 5.65342e+09 4.24571e+08 NaN
2018 4.50866e+10 5.94399e+08 8e+09
2020 6.66498e+10 1.00836e+09 1.33672e+10
2022 1.09123e+11 9.51039e+08 2.59738e+10
2025 1.53003e+11 1.27371e+09 3.94102e+10
EOD
$bsdf_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.85757e+09 4.46463e+08 NaN
2017 7.22516e+09 6.42164e+08 NaN
2018 6.02187e+10 8.17299e+08 1e+10
2020 7.96668e+10 1.24187e+09 1.59024e+10
2022 1.84886e+11 1.3374e+09 4.40196e+10
2025 2.84801e+11 2.3776e+09 7.32891e+10
EOD
set output 'cornell_roofline_bsdf.png'
set title "cornell, bsdf: rays/s that 1080p60 needs against each GPU's limits (3.31 rays per path)"
plot $bsdf_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bsdf_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bsdf_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bsdf_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bsdf_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bsdf_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.59729e+13 with lines lc 'black' dt 3 lw 2 title 'need: none, 3.88e+04 spp'

$nee_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.07865e+09 3.02618e+08 NaN
2016 5.48448e+09 4.32312e+08 NaN
2018 3.59496e+10 6.05237e+08 8e+09
2020 5.31429e+10 1.02674e+09 1.33672e+10
2022 8.70084e+10 9.68379e+08 2.59738e+10
2025 1.27108e+11 1.29694e+09 3.94102e+10
EOD
$nee_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.7423e+09 4.54603e+08 NaN
2017 7.00925e+09 6.53872e+08 NaN
2018 4.8015e+10 8.32201e+08 1e+10
2020 6.35219e+10 1.26451e+09 1.59024e+10
2022 1.47418e+11 1.36178e+09 4.40196e+10
2025 2.366e+11 2.42095e+09 7.32891e+10
EOD
set output 'cornell_roofline_nee.png'
set title "cornell, nee: rays/s that 1080p60 needs against each GPU's limits (5.20 rays per path)"
plot $nee_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $nee_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $nee_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $nee_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $nee_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $nee_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.42451e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 220 spp', \
     3.717e+10 with lines lc 'black' dt 4 lw 2 title 'need: atrous, 57.5 spp'

$bdpt_x80 << EOD
# year fp32 memory rt_cores (rays per second)
2014 3.11855e+09 2.9937e+08 NaN
2016 5.55557e+09 4.27672e+08 NaN
2018 4.22526e+10 5.98741e+08 8e+09
2020 6.24604e+10 1.01572e+09 1.33672e+10
2022 1.02264e+11 9.57985e+08 2.59738e+10
2025 1.50155e+11 1.28302e+09 3.94102e+10
EOD
$bdpt_flagship << EOD
# year fp32 memory rt_cores (rays per second)
2015 3.7908e+09 4.49724e+08 NaN
2017 7.1001e+09 6.46854e+08 NaN
2018 5.64335e+10 8.23269e+08 1e+10
2020 7.46591e+10 1.25094e+09 1.59024e+10
2022 1.73265e+11 1.34717e+09 4.40196e+10
2025 2.795e+11 2.39496e+09 7.32891e+10
EOD
set output 'cornell_roofline_bdpt.png'
set title "cornell, bdpt: rays/s that 1080p60 needs against each GPU's limits (10.76 rays per path)"
plot $bdpt_x80 using 1:2 with linespoints lc rgb '#1f77b4' dt 1 pt 7 title 'x80: FP32', \
     $bdpt_x80 using 1:3 with linespoints lc rgb '#2ca02c' dt 1 pt 7 title 'x80: memory', \
     $bdpt_x80 using 1:4 with linespoints lc rgb '#d62728' dt 1 pt 7 title 'x80: RT cores', \
     $bdpt_flagship using 1:2 with linespoints lc rgb '#1f77b4' dt 2 pt 5 title 'flagship: FP32', \
     $bdpt_flagship using 1:3 with linespoints lc rgb '#2ca02c' dt 2 pt 5 title 'flagship: memory', \
     $bdpt_flagship using 1:4 with linespoints lc rgb '#d62728' dt 2 pt 5 title 'flagship: RT cores', \
     1.51513e+11 with lines lc 'black' dt 3 lw 2 title 'need: none, 113 spp', \
     3.71188e+10 with lines lc 'black' dt 4 lw 2 title 'need: atrous, 27.7 spp'
