// stochtex analyze: one report page on the stationary zoom texture's
// artifacts — sliding, contrast loss and its corrections, correlation — with
// every image and table of the `zoom`, `contrast` and `correlation` studies.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "common.h"
#include "stochtex/analysis/plot.h"
#include "stochtex/analysis/zoom_statistics.h"
#include "stochtex/core/parallel.h"
#include "stochtex/image/image_io.h"
#include "zoom_studies.h"

namespace stochtex::cli {
namespace fs = std::filesystem;


void registerAnalyze(CLI::App& app) {
    struct Args {
        ZoomFlags zoom;
        CorrelationStudy correlation;
        ContrastStudy contrast;
        std::string dir;
        int threads = 0;
    };
    auto args = std::make_shared<Args>();
    auto* cmd = app.add_subcommand("analyze", "Report page (index.html) on the zoom texture's artifacts: sliding, "
                                              "contrast loss and corrections, correlation plots");
    cmd->add_option("-o,--output", args->dir, "Output folder (index.html and the figures)")->required();
    cmd->add_option("--instances", args->correlation.instances, "Instances N for the measured correlation plots");
    cmd->add_option("--plot-size", args->correlation.size, "Extent of the correlation plots in pixels");
    cmd->add_option("--layers-list", args->correlation.layers, "Layer counts of the correlation grid")->delimiter(',');
    cmd->add_option("--size", args->contrast.size, "Size of the contrast-correction textures");
    addZoomFlags(*cmd, args->zoom, false);
    addThreadsFlag(*cmd, args->threads);
    cmd->callback([args] {
        ThreadLimit limit(args->threads);
        const auto start = std::chrono::steady_clock::now();
        validateStudy(args->zoom, args->correlation);
        validateStudy(args->zoom, args->contrast);
        ensureFolder(args->dir);
        const std::string zoomDir = (fs::path(args->dir) / "zoom").string();
        ensureFolder(zoomDir);

        // Sliding: the same frame pair for eq. 2.2 and eq. 2.5, and the
        // layers' scales over time.
        std::fprintf(stderr, "analyze: zoom frames and layer scales\n");
        std::vector<Figure> zoomFigures;
        {
            std::vector<Image> row;
            std::vector<std::string> names;
            for (const char* scaling : {"sliding", "exponential"}) {
                ZoomFlags f = args->zoom;
                f.scaling = scaling;
                for (double t : {0.0, 0.5}) {
                    f.time = t;
                    const ZoomParams p = makeZoomParams(f);
                    row.push_back(renderZoom(makeBase(f), p, ZoomRegion::centred(256, 256)));
                    char c[64];
                    std::snprintf(c, sizeof c, "%s, t = %.1f", scaling, t);
                    names.push_back(c);
                }
            }
            writeImage((fs::path(zoomDir) / "frames.png").string(), sheet({row}, {names}));
            zoomFigures.push_back({"frames.png", "The zoom texture (n = " + std::to_string(args->zoom.layers) +
                                                     ") with sliding scales (eq. 2.2) and with the exponential fix "
                                                     "(eq. 2.5), half a time unit apart."});
            std::vector<PlotSeries> series;
            for (const char* scaling : {"sliding", "exponential"}) {
                PlotSeries s{std::string(scaling) + ": layer 0 scale a_0(t)", {}, {},
                             scaling[0] == 's' ? std::array<float, 3>{0.8f, 0.2f, 0.1f}
                                               : std::array<float, 3>{0.1f, 0.3f, 0.8f}};
                ZoomFlags f = args->zoom;
                f.scaling = scaling;
                for (int i = 0; i <= 400; ++i) {
                    f.time = 4.0 * i / 400.0;
                    s.x.push_back(f.time);
                    s.y.push_back(zoomLayers(makeZoomParams(f), 2, 2)[0].scale);
                }
                series.push_back(s);
            }
            LinePlotOptions o;
            o.title = "Scale of one layer over time";
            o.xLabel = "t";
            o.yLabel = "a_0";
            writeImage((fs::path(zoomDir) / "scales.png").string(), linePlot(series, o));
            zoomFigures.push_back({"scales.png", "a_0(t): linear ramps (sliding: screen speed 1/a differs per "
                                                 "layer) vs exponential decay (every layer moves at the same "
                                                 "relative speed −a'/a = 1)."});
        }
        const StudyOutput contrast = runContrastStudy(args->zoom, args->contrast, (fs::path(args->dir) / "contrast").string());
        const StudyOutput correlation =
            runCorrelationStudy(args->zoom, args->correlation, (fs::path(args->dir) / "correlation").string());
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        std::ostringstream html;
        html << "<!doctype html><html><head><meta charset='utf-8'><title>stochtex: zoom texture artifacts</title>"
                "<style>body{font-family:sans-serif;max-width:1200px;margin:2em auto;color:#222}"
                "figure{display:inline-block;margin:0 1em 1.5em 0;vertical-align:top;max-width:100%}"
                "img{max-width:100%}figcaption{max-width:560px;font-size:90%}table{border-collapse:collapse;margin:1em 0}"
                "td,th{border:1px solid #bbb;padding:.25em .6em;text-align:right}</style></head><body>"
                "<h1>Stationary zoom texture: artifacts and fixes</h1>"
                "<p>I(x) = &Sigma;<sub>i</sub> A(a<sub>i</sub>) g(a<sub>i</sub> x + o<sub>i</sub>) (Tavernier 2017, eq. "
                "2.1) over a white-noise lattice; statistics are over the space of lattice realisations. Generated by "
                "<code>stochtex analyze</code> in "
             << int(seconds) << " s.</p>\n<h2>Sliding (section 2.2)</h2>\n";
        html << htmlFigures("zoom/", zoomFigures, 100);
        html << "<h2>Contrast loss and its corrections (section 2.4)</h2>\n"
                "<p>Var I(x) = &sigma;<sub>f</sub>&sup2; &alpha;(x, x) &lt; &sigma;<sub>f</sub>&sup2;: the blend loses "
                "contrast. Each correction uses the per-pixel analytic variance.</p>"
             << markdownToHtml(contrast.table);
        html << htmlFigures("contrast/", contrast.figures, 100);
        html << "<h2>Correlation (section 2.5)</h2>\n<p>Mean |analytic &minus; measured| over the plots, and the "
                "largest analytic correlation away from the diagonal band |x &minus; y| &le; 4 (the interpolation "
                "kernel's own correlation). Hashed (random) offsets remove the echoes.</p>"
             << markdownToHtml(correlation.table);
        html << htmlFigures("correlation/", correlation.figures, 1);
        html << "<h3>Each variant at n = " << args->correlation.layers.front() << "</h3>\n";
        std::vector<Figure> firstN;
        for (const auto& f : correlation.figures)
            if (f.file.find("_n" + std::to_string(args->correlation.layers.front()) + "_") != std::string::npos)
                firstN.push_back(f);
        html << htmlFigures("correlation/", firstN, 100);
        html << "<p>All plots for every n are in <a href='correlation/'>correlation/</a> "
                "(<a href='correlation/correlation.csv'>correlation.csv</a>).</p></body></html>\n";
        writeFileAtomic((fs::path(args->dir) / "index.html").string(), html.str());
        std::printf("wrote %s (%.1f s)\n", (fs::path(args->dir) / "index.html").string().c_str(), seconds);
    });
}

}  // namespace stochtex::cli
