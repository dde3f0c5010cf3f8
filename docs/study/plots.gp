# Written by `fragpath study` from study.csv in this directory; edit and rerun with
#   gnuplot plots.gp
# Columns: 1 scene, 2 integrator, 3 denoiser, 4 spp, 5 render_seconds, 6 render_cpu_seconds,
# 7 denoise_seconds, 8 total_seconds, 9 rmse, 10 rel_mse, 11 ssim, 12 flip.
set datafile separator ','
set datafile missing NaN
set terminal pngcairo size 800,520 font 'sans,10'
set grid
set key outside right top

# cornell
threshold = 0.0004  # relative MSE under which the report calls an image not noisy
budget_ms = 16.6667  # one frame at 60 FPS
set yrange [0.000117238:53.7444]
set logscale xy

set output 'cornell_error_vs_spp.png'
set title 'cornell: error against samples per pixel'
set xlabel 'samples per pixel'
set ylabel 'relative MSE'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'

set output 'cornell_error_vs_time.png'
set title 'cornell: error against render time (this machine; median of the runs)'
set xlabel 'render + denoise time (ms)'
set xrange [4.65775:10680.4]
set arrow 1 from budget_ms, graph 0 to budget_ms, graph 1 nohead lc 'red' dt 2 lw 2
set label 1 '60 FPS frame budget (16.7 ms)' at budget_ms, graph 0.95 offset 0.5, 0 tc 'red'
plot 'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'
unset arrow 1
unset label 1

set output 'cornell_ssim_vs_spp.png'
set title 'cornell: structural similarity against samples per pixel'
unset logscale y
set yrange [0:1]
set xlabel 'samples per pixel'
set ylabel 'SSIM (display luma)'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous'

# cornell-checker
threshold = 0.0004  # relative MSE under which the report calls an image not noisy
budget_ms = 16.6667  # one frame at 60 FPS
set yrange [0.000107699:50.6726]
set logscale xy

set output 'cornell-checker_error_vs_spp.png'
set title 'cornell-checker: error against samples per pixel'
set xlabel 'samples per pixel'
set ylabel 'relative MSE'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'

set output 'cornell-checker_error_vs_time.png'
set title 'cornell-checker: error against render time (this machine; median of the runs)'
set xlabel 'render + denoise time (ms)'
set xrange [6.93706:9012.55]
set arrow 1 from budget_ms, graph 0 to budget_ms, graph 1 nohead lc 'red' dt 2 lw 2
set label 1 '60 FPS frame budget (16.7 ms)' at budget_ms, graph 0.95 offset 0.5, 0 tc 'red'
plot 'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'
unset arrow 1
unset label 1

set output 'cornell-checker_ssim_vs_spp.png'
set title 'cornell-checker: structural similarity against samples per pixel'
unset logscale y
set yrange [0:1]
set xlabel 'samples per pixel'
set ylabel 'SSIM (display luma)'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-checker' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous'

# cornell-spheres
threshold = 0.0004  # relative MSE under which the report calls an image not noisy
budget_ms = 16.6667  # one frame at 60 FPS
set yrange [0.0002:51.3224]
set logscale xy

set output 'cornell-spheres_error_vs_spp.png'
set title 'cornell-spheres: error against samples per pixel'
set xlabel 'samples per pixel'
set ylabel 'relative MSE'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'

set output 'cornell-spheres_error_vs_time.png'
set title 'cornell-spheres: error against render time (this machine; median of the runs)'
set xlabel 'render + denoise time (ms)'
set xrange [11.1111:12283.7]
set arrow 1 from budget_ms, graph 0 to budget_ms, graph 1 nohead lc 'red' dt 2 lw 2
set label 1 '60 FPS frame budget (16.7 ms)' at budget_ms, graph 0.95 offset 0.5, 0 tc 'red'
plot 'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'
unset arrow 1
unset label 1

set output 'cornell-spheres_ssim_vs_spp.png'
set title 'cornell-spheres: structural similarity against samples per pixel'
unset logscale y
set yrange [0:1]
set xlabel 'samples per pixel'
set ylabel 'SSIM (display luma)'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'cornell-spheres' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous'

# environment
threshold = 0.0004  # relative MSE under which the report calls an image not noisy
budget_ms = 16.6667  # one frame at 60 FPS
set yrange [0.0002:207.192]
set logscale xy

set output 'environment_error_vs_spp.png'
set title 'environment: error against samples per pixel'
set xlabel 'samples per pixel'
set ylabel 'relative MSE'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'

set output 'environment_error_vs_time.png'
set title 'environment: error against render time (this machine; median of the runs)'
set xlabel 'render + denoise time (ms)'
set xrange [8.03725:2783.17]
set arrow 1 from budget_ms, graph 0 to budget_ms, graph 1 nohead lc 'red' dt 2 lw 2
set label 1 '60 FPS frame budget (16.7 ms)' at budget_ms, graph 0.95 offset 0.5, 0 tc 'red'
plot 'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'
unset arrow 1
unset label 1

set output 'environment_ssim_vs_spp.png'
set title 'environment: structural similarity against samples per pixel'
unset logscale y
set yrange [0:1]
set xlabel 'samples per pixel'
set ylabel 'SSIM (display luma)'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'environment' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous'

# sphere-1m
threshold = 0.0004  # relative MSE under which the report calls an image not noisy
budget_ms = 16.6667  # one frame at 60 FPS
set yrange [0.000126362:45.4335]
set logscale xy

set output 'sphere-1m_error_vs_spp.png'
set title 'sphere-1m: error against samples per pixel'
set xlabel 'samples per pixel'
set ylabel 'relative MSE'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'

set output 'sphere-1m_error_vs_time.png'
set title 'sphere-1m: error against render time (this machine; median of the runs)'
set xlabel 'render + denoise time (ms)'
set xrange [11.1111:15692.3]
set arrow 1 from budget_ms, graph 0 to budget_ms, graph 1 nohead lc 'red' dt 2 lw 2
set label 1 '60 FPS frame budget (16.7 ms)' at budget_ms, graph 0.95 offset 0.5, 0 tc 'red'
plot 'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'
unset arrow 1
unset label 1

set output 'sphere-1m_ssim_vs_spp.png'
set title 'sphere-1m: structural similarity against samples per pixel'
unset logscale y
set yrange [0:1]
set xlabel 'samples per pixel'
set ylabel 'SSIM (display luma)'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'sphere-1m' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous'

# gltf-showcase
threshold = 0.0004  # relative MSE under which the report calls an image not noisy
budget_ms = 16.6667  # one frame at 60 FPS
set yrange [0.0002:4.15851]
set logscale xy

set output 'gltf-showcase_error_vs_spp.png'
set title 'gltf-showcase: error against samples per pixel'
set xlabel 'samples per pixel'
set ylabel 'relative MSE'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'

set output 'gltf-showcase_error_vs_time.png'
set title 'gltf-showcase: error against render time (this machine; median of the runs)'
set xlabel 'render + denoise time (ms)'
set xrange [11.1111:10335.3]
set arrow 1 from budget_ms, graph 0 to budget_ms, graph 1 nohead lc 'red' dt 2 lw 2
set label 1 '60 FPS frame budget (16.7 ms)' at budget_ms, graph 0.95 offset 0.5, 0 tc 'red'
plot 'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? 1000 * $8 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'
unset arrow 1
unset label 1

set output 'gltf-showcase_ssim_vs_spp.png'
set title 'gltf-showcase: structural similarity against samples per pixel'
unset logscale y
set yrange [0:1]
set xlabel 'samples per pixel'
set ylabel 'SSIM (display luma)'
set xrange [0.8:80]
plot 'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'naive' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'naive' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'naive' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bsdf' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bsdf' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bsdf' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'nee' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'nee' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'nee' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bdpt' && strcol(3) eq 'none' ? $4 : NaN):11 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bdpt' && strcol(3) eq 'bilateral' ? $4 : NaN):11 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'gltf-showcase' && strcol(2) eq 'bdpt' && strcol(3) eq 'atrous' ? $4 : NaN):11 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous'
