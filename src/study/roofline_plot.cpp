#include "study/roofline_plot.h"

#include <algorithm>
#include <cmath>

#include "core/text.h"
#include "study/feasibility.h"
#include "study/plots.h"
#include "study/roofline.h"
#include "study/roofline_report.h"

namespace fp::study {

namespace {

std::string value(double v) {
    return std::isfinite(v) ? formatText("%.6g", v) : std::string("NaN");
}

// One inline data block per integrator and class: year, then the FP32, memory and RT-core limits in
// rays per second.
std::string dataBlock(const std::string& name, GpuClass gpuClass, const PathWork& work) {
    std::string text = "$" + name + " << EOD\n# year fp32 memory rt_cores (rays per second)\n";
    for (const Gpu& g : gpusOfClass(gpuClass)) {
        RooflineLimits l = rooflineLimits(g, work);
        double rays = work.counts.rays;
        text += formatText("%d %s %s %s\n", g.year, value(l.compute * rays).c_str(),
                           value(l.memory * rays).c_str(), value(l.rays * rays).c_str());
    }
    return text + "EOD\n";
}

}  // namespace

std::string rooflinePlotName(const std::string& scene, const std::string& integrator) {
    return scene + "_roofline_" + integrator + ".png";
}

std::string rooflineScriptName(const std::string& scene) {
    return scene + "_roofline.gp";
}

std::string rooflineGnuplotScript(const ReportInput& in) {
    std::string script =
        "# Written by `fragpath study` (src/study/roofline_plot.cpp); edit and rerun with\n"
        "#   gnuplot " +
        rooflineScriptName(in.sceneName) + "\n" +
        "set terminal pngcairo size 900,560 font 'sans,10'\nset grid\nset key outside right top\n"
        "set logscale y\nset format y '10^{%T}'\nset xlabel 'year'\nset ylabel 'rays per second'\n"
        "set xrange [2013.5:2025.5]\n";
    const std::vector<FeasibilityRow> rows = feasibilityRows(in);
    for (const std::string& integrator : rooflineIntegrators(in)) {
        PathWork w;
        w.counts = in.counts.at(integrator);
        w.integrator = parseIntegrator(integrator);
        w.lightEntries = in.lightEntries;
        script += "\n" + dataBlock(integrator + "_x80", GpuClass::X80, w) +
                  dataBlock(integrator + "_flagship", GpuClass::Flagship, w);
        script += "set output '" + rooflinePlotName(in.sceneName, integrator) + "'\n";
        script += formatText(
            "set title \"%s, %s: rays/s that 1080p60 needs against each GPU's limits (%.2f rays per "
            "path)\"\n",
            in.sceneName.c_str(), integrator.c_str(), w.counts.rays);
        std::string plot = "plot ";
        const char* limitColours[] = {"#1f77b4", "#2ca02c", "#d62728"};
        const char* limitTitles[] = {"FP32", "memory", "RT cores"};
        for (GpuClass c : {GpuClass::X80, GpuClass::Flagship}) {
            std::string block = "$" + integrator + (c == GpuClass::X80 ? "_x80" : "_flagship");
            for (int column = 0; column < 3; ++column)
                plot += formatText(
                    "%s using 1:%d with linespoints lc rgb '%s' dt %d pt %d title '%s: %s', \\\n     ",
                    block.c_str(), column + 2, limitColours[column], c == GpuClass::X80 ? 1 : 2,
                    c == GpuClass::X80 ? 7 : 5, gpuClassName(c), limitTitles[column]);
        }
        int dash = 3;
        for (const FeasibilityRow& f : rows) {
            if (f.integrator != integrator || f.sppNeeded <= 0) continue;
            double need = requiredPathsPerSecond(f.sppNeeded) * w.counts.rays;
            plot += formatText("%s with lines lc 'black' dt %d lw 2 title 'need: %s, %.3g spp', \\\n     ",
                               value(need).c_str(), dash++, f.denoiser.c_str(), f.sppNeeded);
        }
        script += plot.substr(0, plot.rfind(", \\\n")) + "\n";
    }
    return script;
}

void drawRooflinePlots(const std::string& dir, const ReportInput& in) {
    if (rooflineIntegrators(in).empty()) return;
    runGnuplotScript(dir, rooflineScriptName(in.sceneName), rooflineGnuplotScript(in));
}

}  // namespace fp::study
