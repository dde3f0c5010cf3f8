# Written by `fragpath study` from study.csv in this directory; edit and rerun with
#   gnuplot plots.gp
# Columns: 1 integrator, 2 denoiser, 3 spp, 4 render_seconds, 5 render_cpu_seconds,
# 6 denoise_seconds, 7 total_seconds, 8 rmse, 9 rel_mse, 10 ssim, 11 flip.
set datafile separator ','
set datafile missing NaN
set terminal pngcairo size 800,520 font 'sans,10'
set grid
set key outside right top
threshold = 0.0004  # relative MSE under which the report calls an image not noisy
budget_ms = 16.6667  # one frame at 60 FPS
set yrange [5.14856e-05:57.5718]
set logscale xy

set output 'error_vs_spp.png'
set title 'Error against samples per pixel'
set xlabel 'samples per pixel'
set ylabel 'relative MSE'
set xrange [0.8:640]
plot 'study.csv' every ::1 using (strcol(1) eq 'naive' && strcol(2) eq 'none' ? $3 : NaN):9 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'naive' && strcol(2) eq 'bilateral' ? $3 : NaN):9 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'naive' && strcol(2) eq 'atrous' ? $3 : NaN):9 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'bsdf' && strcol(2) eq 'none' ? $3 : NaN):9 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'bsdf' && strcol(2) eq 'bilateral' ? $3 : NaN):9 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'bsdf' && strcol(2) eq 'atrous' ? $3 : NaN):9 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'nee' && strcol(2) eq 'none' ? $3 : NaN):9 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'nee' && strcol(2) eq 'bilateral' ? $3 : NaN):9 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'nee' && strcol(2) eq 'atrous' ? $3 : NaN):9 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'bdpt' && strcol(2) eq 'none' ? $3 : NaN):9 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'bdpt' && strcol(2) eq 'bilateral' ? $3 : NaN):9 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'bdpt' && strcol(2) eq 'atrous' ? $3 : NaN):9 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'

set output 'error_vs_time.png'
set title 'Error against render time (this machine; median of the runs)'
set xlabel 'render + denoise time (ms)'
set xrange [5.00514:56450.9]
set arrow 1 from budget_ms, graph 0 to budget_ms, graph 1 nohead lc 'red' dt 2 lw 2
set label 1 '60 FPS frame budget (16.7 ms)' at budget_ms, graph 0.95 offset 0.5, 0 tc 'red'
plot 'study.csv' every ::1 using (strcol(1) eq 'naive' && strcol(2) eq 'none' ? 1000 * $7 : NaN):9 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'naive' && strcol(2) eq 'bilateral' ? 1000 * $7 : NaN):9 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'naive' && strcol(2) eq 'atrous' ? 1000 * $7 : NaN):9 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'bsdf' && strcol(2) eq 'none' ? 1000 * $7 : NaN):9 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'bsdf' && strcol(2) eq 'bilateral' ? 1000 * $7 : NaN):9 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'bsdf' && strcol(2) eq 'atrous' ? 1000 * $7 : NaN):9 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'nee' && strcol(2) eq 'none' ? 1000 * $7 : NaN):9 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'nee' && strcol(2) eq 'bilateral' ? 1000 * $7 : NaN):9 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'nee' && strcol(2) eq 'atrous' ? 1000 * $7 : NaN):9 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'bdpt' && strcol(2) eq 'none' ? 1000 * $7 : NaN):9 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'bdpt' && strcol(2) eq 'bilateral' ? 1000 * $7 : NaN):9 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'bdpt' && strcol(2) eq 'atrous' ? 1000 * $7 : NaN):9 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous', \
     threshold with lines lc 'black' dt 3 title 'noise threshold'
unset arrow 1
unset label 1

set output 'ssim_vs_spp.png'
set title 'Structural similarity against samples per pixel'
unset logscale y
set yrange [0:1]
set xlabel 'samples per pixel'
set ylabel 'SSIM (display luma)'
set xrange [0.8:640]
plot 'study.csv' every ::1 using (strcol(1) eq 'naive' && strcol(2) eq 'none' ? $3 : NaN):10 with linespoints lc 1 dt 1 pt 6 title 'naive', \
     'study.csv' every ::1 using (strcol(1) eq 'naive' && strcol(2) eq 'bilateral' ? $3 : NaN):10 with linespoints lc 1 dt 2 pt 7 title 'naive + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'naive' && strcol(2) eq 'atrous' ? $3 : NaN):10 with linespoints lc 1 dt 3 pt 8 title 'naive + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'bsdf' && strcol(2) eq 'none' ? $3 : NaN):10 with linespoints lc 2 dt 1 pt 6 title 'bsdf', \
     'study.csv' every ::1 using (strcol(1) eq 'bsdf' && strcol(2) eq 'bilateral' ? $3 : NaN):10 with linespoints lc 2 dt 2 pt 7 title 'bsdf + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'bsdf' && strcol(2) eq 'atrous' ? $3 : NaN):10 with linespoints lc 2 dt 3 pt 8 title 'bsdf + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'nee' && strcol(2) eq 'none' ? $3 : NaN):10 with linespoints lc 3 dt 1 pt 6 title 'nee', \
     'study.csv' every ::1 using (strcol(1) eq 'nee' && strcol(2) eq 'bilateral' ? $3 : NaN):10 with linespoints lc 3 dt 2 pt 7 title 'nee + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'nee' && strcol(2) eq 'atrous' ? $3 : NaN):10 with linespoints lc 3 dt 3 pt 8 title 'nee + atrous', \
     'study.csv' every ::1 using (strcol(1) eq 'bdpt' && strcol(2) eq 'none' ? $3 : NaN):10 with linespoints lc 4 dt 1 pt 6 title 'bdpt', \
     'study.csv' every ::1 using (strcol(1) eq 'bdpt' && strcol(2) eq 'bilateral' ? $3 : NaN):10 with linespoints lc 4 dt 2 pt 7 title 'bdpt + bilateral', \
     'study.csv' every ::1 using (strcol(1) eq 'bdpt' && strcol(2) eq 'atrous' ? $3 : NaN):10 with linespoints lc 4 dt 3 pt 8 title 'bdpt + atrous'
