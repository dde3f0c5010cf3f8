#include "study/plots.h"

#include <unistd.h>

#include <sys/wait.h>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/error.h"
#include "image/file_io.h"

namespace fp::study {

namespace {

struct Series {
    std::string integrator, denoiser;
};

std::vector<Series> seriesOf(const std::vector<StudyRow>& rows) {
    std::vector<Series> series;
    for (const StudyRow& r : rows) {  // rows of one scene
        bool known = std::any_of(series.begin(), series.end(), [&](const Series& s) {
            return s.integrator == r.integrator && s.denoiser == r.denoiser;
        });
        if (!known) series.push_back({r.integrator, r.denoiser});
    }
    return series;
}

// A gnuplot `plot` list: one line per series, colour by integrator, dash pattern by denoiser.
std::string plotClauses(const std::string& scene, const std::vector<Series>& series, const std::string& x,
                        const std::string& y) {
    std::vector<std::string> integrators, denoisers;
    auto indexOf = [](std::vector<std::string>& list, const std::string& name) {
        auto it = std::find(list.begin(), list.end(), name);
        if (it != list.end()) return int(it - list.begin());
        list.push_back(name);
        return int(list.size()) - 1;
    };
    std::string text;
    for (const Series& s : series) {
        int colour = indexOf(integrators, s.integrator) + 1, dash = indexOf(denoisers, s.denoiser) + 1;
        std::string title = s.denoiser == "none" ? s.integrator : s.integrator + " + " + s.denoiser;
        text += (text.empty() ? std::string("plot ") : std::string(", \\\n     ")) +
                "'study.csv' every ::1 using (strcol(1) eq '" + scene + "' && strcol(2) eq '" + s.integrator +
                "' && strcol(3) eq '" + s.denoiser + "' ? " + x + " : NaN):" + y + " with linespoints lc " +
                std::to_string(colour) + " dt " + std::to_string(dash) + " pt " + std::to_string(dash + 5) +
                " title '" + title + "'";
    }
    return text;
}

std::string quoteForShell(const std::string& text) {
    std::string quoted = "'";
    for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

}  // namespace

std::vector<std::string> plotFileNames(const std::string& scene) {
    return {scene + "_error_vs_spp.png", scene + "_error_vs_time.png", scene + "_ssim_vs_spp.png"};
}

namespace {

// The three plots of one scene's rows.
std::string scenePlots(const std::string& scene, const std::vector<StudyRow>& rows, double relMseThreshold) {
    // Ranges that always show the threshold and the frame budget, even when every point is far from them.
    double tMin = kFrameBudgetSeconds, tMax = kFrameBudgetSeconds, eMin = relMseThreshold,
           eMax = relMseThreshold;
    int sppMax = 1;
    for (const StudyRow& r : rows) {
        tMin = std::min(tMin, r.totalSeconds()), tMax = std::max(tMax, r.totalSeconds());
        if (r.relMse > 0) eMin = std::min(eMin, r.relMse), eMax = std::max(eMax, r.relMse);
        sppMax = std::max(sppMax, r.spp);
    }
    const std::vector<Series> series = seriesOf(rows);
    char ranges[512];
    std::snprintf(ranges, sizeof ranges,
                  "threshold = %.6g  # relative MSE under which the report calls an image not noisy\n"
                  "budget_ms = %.6g  # one frame at 60 FPS\n"
                  "set yrange [%.6g:%.6g]\n",
                  relMseThreshold, 1000.0 * kFrameBudgetSeconds, eMin / 2, eMax * 2);
    char sppRange[128], timeRange[128];
    std::snprintf(sppRange, sizeof sppRange, "set xrange [0.8:%.6g]\n", sppMax * 1.25);
    std::snprintf(timeRange, sizeof timeRange, "set xrange [%.6g:%.6g]\n", 1000 * tMin / 1.5,
                  1000 * tMax * 1.5);
    const std::vector<std::string> names = plotFileNames(scene);
    const std::string& names0 = names[0];
    const std::string& names1 = names[1];
    const std::string& names2 = names[2];
    return "\n# " + scene + "\n" + ranges + "set logscale xy\n" + "\nset output '" + names0 + "'\n" +
           "set title '" + scene + ": error against samples per pixel'\n" +
           "set xlabel 'samples per pixel'\nset ylabel 'relative MSE'\n" + sppRange +
           plotClauses(scene, series, "$4", "10") +
           ", \\\n     threshold with lines lc 'black' dt 3 title 'noise threshold'\n" + "\nset output '" +
           names1 + "'\n" + "set title '" + scene +
           ": error against render time (this machine; median of the runs)'\n" +
           "set xlabel 'render + denoise time (ms)'\n" + timeRange +
           "set arrow 1 from budget_ms, graph 0 to budget_ms, graph 1 nohead lc 'red' dt 2 lw 2\n" +
           "set label 1 '60 FPS frame budget (16.7 ms)' at budget_ms, graph 0.95 offset 0.5, 0 tc 'red'\n" +
           plotClauses(scene, series, "1000 * $8", "10") +
           ", \\\n     threshold with lines lc 'black' dt 3 title 'noise threshold'\n" +
           "unset arrow 1\nunset label 1\n" + "\nset output '" + names2 + "'\n" + "set title '" + scene +
           ": structural similarity against samples per pixel'\n" + "unset logscale y\nset yrange [0:1]\n" +
           "set xlabel 'samples per pixel'\nset ylabel 'SSIM (display luma)'\n" + sppRange +
           plotClauses(scene, series, "$4", "11") + "\n";
}

}  // namespace

std::string gnuplotScript(const std::vector<StudyRow>& rows, double relMseThreshold) {
    std::string script =
        std::string("# Written by `fragpath study` from study.csv in this directory; edit and rerun with\n") +
        "#   gnuplot plots.gp\n" +
        "# Columns: 1 scene, 2 integrator, 3 denoiser, 4 spp, 5 render_seconds, 6 render_cpu_seconds,\n" +
        "# 7 denoise_seconds, 8 total_seconds, 9 rmse, 10 rel_mse, 11 ssim, 12 flip.\n" +
        "set datafile separator ','\n" +
        // A clause maps the other series' rows to NaN; as "missing" they do not break its line.
        "set datafile missing NaN\n" + "set terminal pngcairo size 800,520 font 'sans,10'\n" + "set grid\n" +
        "set key outside right top\n";
    std::vector<std::string> scenes;
    for (const StudyRow& r : rows)
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
    for (const std::string& scene : scenes) {
        std::vector<StudyRow> own;
        for (const StudyRow& r : rows)
            if (r.scene == scene) own.push_back(r);
        // Each scene's block sets its own ranges and log scales again, after the previous SSIM plot.
        script += scenePlots(scene, own, relMseThreshold);
    }
    return script;
}

void requireGnuplot() {
    const char* path = std::getenv("PATH");
    std::string paths = path ? path : "";
    size_t start = 0;
    while (start <= paths.size()) {
        size_t end = std::min(paths.find(':', start), paths.size());
        std::string dir = paths.substr(start, end - start);
        std::string candidate = (dir.empty() ? std::string(".") : dir) + "/gnuplot";
        if (access(candidate.c_str(), X_OK) == 0) return;
        start = end + 1;
    }
    throw Error(
        "the study draws its plots with gnuplot, which is not on PATH: install it (Debian: apt-get install "
        "gnuplot-nox, or tools/install-deps.sh), or pass --no-plots");
}

void drawPlots(const std::string& dir, const std::vector<StudyRow>& rows, double relMseThreshold) {
    runGnuplotScript(dir, "plots.gp", gnuplotScript(rows, relMseThreshold));
}

void runGnuplotScript(const std::string& dir, const std::string& file, const std::string& script) {
    writeFileAtomically((std::filesystem::path(dir) / file).string(),
                        std::vector<std::uint8_t>(script.begin(), script.end()));
    std::string command = "cd " + quoteForShell(dir) + " && gnuplot " + quoteForShell(file) + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) throw Error("could not start gnuplot");
    std::string output;
    char buffer[1024];
    while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) output.append(buffer, n);
    int status = pclose(pipe);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw Error("gnuplot failed on " + dir + "/" + file + ":\n" + output);
}

}  // namespace fp::study
