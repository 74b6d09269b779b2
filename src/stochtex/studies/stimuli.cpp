#include "stochtex/studies/stimuli.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "stochtex/core/budget.h"
#include "stochtex/core/embedded_file.h"
#include "stochtex/core/error.h"
#include "stochtex/core/hash.h"
#include "stochtex/noise/tiled_white_noise.h"
#include "stochtex/report/plot.h"

namespace stochtex {

extern const EmbeddedFile kEmbeddedExperimentJs[];
extern const std::size_t kEmbeddedExperimentJsCount;

namespace {

void checkMeanContrast(double mean, double contrast) {
    if (!(mean > 0.0 && mean < 1.0)) throw InputError::parameter("mean", "must be in (0, 1), got " + formatValue(mean));
    if (!(contrast > 0.0 && contrast <= 1.0))
        throw InputError::parameter("contrast", "must be in (0, 1], got " + formatValue(contrast));
}

void checkTile(int tile, int size, const std::string& parameter) {
    if (tile < 1 || tile > size || size % tile != 0)
        throw InputError::parameter(parameter, "must hold tile sizes that divide size = " + std::to_string(size) +
                                                   ", got " + std::to_string(tile));
}

std::string correlationName(double c) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", c);
    return buffer;
}

// The mean grey as a CSS colour: the code the stimuli's mean rounds to.
std::string cssGrey(double mean) {
    const long code = std::lround(255.0 * mean);
    return "rgb(" + std::to_string(code) + "," + std::to_string(code) + "," + std::to_string(code) + ")";
}

std::string experimentPage(const StimulusSetOptions& o, const std::vector<StimulusTrial>& trials,
                           const std::vector<Figure>& images) {
    if (kEmbeddedExperimentJsCount != 1) throw std::logic_error("stimulusSet: experiment.js is not embedded");
    nlohmann::ordered_json config = {
        {"size", o.size}, {"durationMs", o.durationMs}, {"resetMs", o.resetMs}, {"trials", nlohmann::json::array()}};
    std::ostringstream stage;
    for (size_t i = 0; i < trials.size(); ++i) {
        const StimulusTrial& t = trials[i];
        config["trials"].push_back(nlohmann::ordered_json{{"trial", t.trial},
                                                          {"stimulus", t.stimulus},
                                                          {"w", t.tile},
                                                          {"correlation", t.correlation},
                                                          {"alpha", t.alpha}});
        // Every stimulus is an element of the page, loaded before its load
        // event: nothing is fetched or decoded between trials.
        stage << "<img id='stimulus-" << t.trial << "' class='stimulus' alt='' src='" << pngDataUri(images[i].image)
              << "'>";
    }
    const std::string grey = cssGrey(o.mean);
    const double minutes = trials.size() * (o.resetMs + o.durationMs + 1500.0) / 60000.0;
    std::ostringstream h;
    h << "<style>body{max-width:none;margin:0;background:" << grey
      << ";color:#000}"
         "#stage{position:fixed;inset:0;display:flex;align-items:center;justify-content:center;pointer-events:none}"
         ".stimulus{image-rendering:pixelated;visibility:hidden;display:none}"
         ".panel{position:relative;max-width:42em;margin:4em auto;padding:0 1em;font-size:110%}"
         "#question{text-align:center;margin-top:40vh}button{font-size:120%;margin:0 .5em;padding:.3em 1.2em}"
         "pre{background:#eee;padding:.5em;max-height:20em;overflow:auto}</style>\n"
         "<div id='stage'>"
      << stage.str()
      << "</div>\n"
         "<div id='intro' class='panel'><h1>Do you see a repeating pattern?</h1>"
         "<p>You will see "
      << trials.size() << " noise images, one at a time (about " << std::lround(std::max(1.0, minutes))
      << (std::lround(std::max(1.0, minutes)) == 1 ? " minute" : " minutes") << "). Each trial: a grey screen for "
      << o.resetMs << " ms, then an image for " << o.durationMs
      << " ms, then grey again.</p>"
         "<p>Some images contain a square patch of noise that repeats side by side, like tiles; others do not. "
         "After each image, answer: <b>did you see a repeating pattern?</b> Press <b>Y</b> for yes or <b>N</b> for no "
         "(or click the buttons). Go by your impression; answer quickly.</p>"
         "<p>Keep your eyes on the centre of the screen. Use a dim room and a fixed viewing distance, and do not zoom "
         "the page: the images are shown one image pixel per screen pixel.</p>"
         "<p><button id='start' disabled>Start</button> (or press Space)</p></div>\n"
         "<div id='question' class='panel' hidden><p><b>Repeating pattern?</b></p>"
         "<p><button id='yes'>Yes (Y)</button><button id='no'>No (N)</button></p><p id='progress'></p></div>\n"
         "<div id='done' class='panel' hidden><h1>Thank you</h1><p><a id='download' download='answers.csv'>"
         "Download the answers (answers.csv)</a>, or copy them from below.</p><pre id='answers-csv'></pre></div>\n"
         "<script type='application/json' id='experiment-config'>"
      << config.dump() << "</script>\n<script>" << kEmbeddedExperimentJs[0].contents << "</script>\n";
    return h.str();
}

}  // namespace

double stimulusAmplitude(double mean, double contrast) {
    return contrast * std::min(mean, 1.0 - mean) / std::sqrt(2.0);
}

void validateStimulus(const StimulusOptions& o) {
    if (o.size < 1 || o.size > 4096)
        throw InputError::parameter("size", "must be in [1, 4096], got " + std::to_string(o.size));
    checkTile(o.tile, o.size, "tile");
    blendAlphaForCorrelation(o.correlation);
    checkMeanContrast(o.mean, o.contrast);
}

Image stimulusImage(const StimulusOptions& o) {
    validateStimulus(o);
    Image image = tiledWhiteNoise({o.size, o.tile, blendAlphaForCorrelation(o.correlation), o.seed});
    // |Z| ≤ √2 and a ≤ min(mean, 1 − mean)/√2: display values stay in [0, 1].
    const float mean = float(o.mean), a = float(stimulusAmplitude(o.mean, o.contrast));
    for (float& v : image.data()) v = std::clamp(mean + a * v, 0.0f, 1.0f);  // the clamp guards float rounding only
    return image;
}

std::span<const OptionMember<StimulusSetOptions>> stimulusSetMembers() {
    using O = StimulusSetOptions;
    static const OptionMember<O> members[] = {
        {"size", "Stimulus side, pixels (shown 1:1)", 8, 2048, &O::size},
        {"repeats", "Stimuli per (w, correlation)", 1, 1000, &O::repeats},
        {"durationMs", "Time a stimulus is shown, ms", 1, 60000, &O::durationMs},
        {"resetMs", "Mean-grey screen before each stimulus, ms", 0, 60000, &O::resetMs},
    };
    return members;
}

void validateStimulusSet(const StimulusSetOptions& o) {
    checkMembers(o, stimulusSetMembers());
    if (o.tiles.empty()) throw InputError::parameter("tiles", "must hold at least one tile size");
    for (int w : o.tiles) checkTile(w, o.size, "tiles");
    if (std::set<int>(o.tiles.begin(), o.tiles.end()).size() != o.tiles.size())
        throw InputError::parameter("tiles", "must not repeat a tile size");
    if (o.correlations.empty()) throw InputError::parameter("correlations", "must hold at least one correlation");
    for (double c : o.correlations)
        if (!(c >= 0.0 && c <= 1.0))
            throw InputError::parameter("correlations", "must hold values in [0, 1], got " + formatValue(c));
    std::set<std::string> names;
    for (double c : o.correlations) names.insert(correlationName(c));
    if (names.size() != o.correlations.size())
        throw InputError::parameter("correlations", "must not repeat a correlation");
    checkMeanContrast(o.mean, o.contrast);
    const long long trials = (long long)o.tiles.size() * (long long)o.correlations.size() * o.repeats;
    if (trials > kMaxStimulusTrials)
        throw InputError::parameter(
            "repeats", "gives " + std::to_string(trials) + " trials, more than " + std::to_string(kMaxStimulusTrials));
    if (trials * o.size * o.size > budgeted(kMaxStimulusPixels))
        throw InputError::overBudget("size", "size gives " + std::to_string(trials) + " stimuli of " +
                                                 std::to_string(o.size) + "² pixels, more than " +
                                                 std::to_string(budgeted(kMaxStimulusPixels)) + " pixels in all");
}

std::vector<int> stimulusTrialOrder(int count, uint32_t seed) {
    std::vector<int> order(std::max(count, 0));
    for (int i = 0; i < count; ++i) order[i] = i;
    for (int i = count - 1; i > 0; --i) {
        // j uniform in [0, i]: 24-bit unit float times i + 1 (bias below 2⁻²⁴·count).
        const int j = std::min(i, int(unitFloat(pcg3d({seed, uint32_t(i), 0x9e3779b9u}).x) * float(i + 1)));
        std::swap(order[i], order[j]);
    }
    return order;
}

StimulusSet stimulusSet(const StimulusSetOptions& o, const StudyProgress& progress) {
    validateStimulusSet(o);
    std::vector<StimulusTrial> grid;
    for (int w : o.tiles)
        for (double c : o.correlations)
            for (int r = 1; r <= o.repeats; ++r) {
                StimulusTrial t;
                // Appended piece by piece: "w" + std::string trips GCC 12's -Wrestrict false positive.
                t.stimulus = "w";
                t.stimulus += std::to_string(w) + "_c" + correlationName(c) + "_r" + std::to_string(r) + ".png";
                t.tile = w;
                t.correlation = c;
                t.alpha = blendAlphaForCorrelation(c);
                t.repeat = r;
                t.seed = deriveSeed(o.seed, uint32_t(1 + grid.size()));
                grid.push_back(t);
            }
    const std::vector<int> order = stimulusTrialOrder(int(grid.size()), deriveSeed(o.seed, 0));
    StimulusSet set;
    set.listing.columns = {{"trial", "trial", ""},
                           {"stimulus", "stimulus", ""},
                           {"w", "tile size w", "pixels"},
                           {"correlation", "correlation", ""},
                           {"alpha", "α", ""},
                           {"repeat", "repeat", ""},
                           {"seed", "seed", ""}};
    for (size_t k = 0; k < order.size(); ++k) {
        StimulusTrial t = grid[order[k]];
        t.trial = int(k) + 1;
        set.images.push_back(
            {t.stimulus, stimulusImage({o.size, t.tile, t.correlation, t.seed, o.mean, o.contrast}), ""});
        set.listing.add({TableCell::integer(t.trial), t.stimulus, TableCell::integer(t.tile),
                         TableCell::value(t.correlation, "%g"), TableCell::value(t.alpha, "%.6f"),
                         TableCell::integer(t.repeat), std::to_string(t.seed)});
        set.trials.push_back(t);
        if (progress) progress(double(k + 1) / double(order.size() + 1), "stimuli");
    }
    set.page = experimentPage(o, set.trials, set.images);
    if (progress) progress(1.0, "page");
    return set;
}

double tileToTileCorrelation(const Image& image, int tile) {
    double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    long long n = 0;
    const auto pair = [&](double a, double b) {
        sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b;
        ++n;
    };
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            if (x + tile < image.width()) pair(image.at(x, y), image.at(x + tile, y));
            if (y + tile < image.height()) pair(image.at(x, y), image.at(x, y + tile));
        }
    if (n < 2) return std::nan("");
    const double cov = sab / n - (sa / n) * (sb / n);
    const double va = saa / n - (sa / n) * (sa / n), vb = sbb / n - (sb / n) * (sb / n);
    return cov / std::sqrt(va * vb);
}

StimulusOverview stimulusOverview(const StimulusSetOptions& o) {
    validateStimulusSet(o);
    StimulusOverview r;
    r.table.columns = {{"w", "tile size w", "pixels"},
                       {"correlation", "correlation asked", ""},
                       {"alpha", "α", ""},
                       {"measured", "measured one tile apart", ""},
                       {"pairs", "pixel pairs", ""}};
    std::vector<std::vector<Image>> rows;
    std::vector<std::vector<std::string>> captions;
    uint32_t index = 0;
    for (int w : o.tiles) {
        rows.emplace_back();
        captions.emplace_back();
        for (double c : o.correlations) {
            const Image s = stimulusImage(
                {o.size, w, c, deriveSeed(o.seed, 1 + index++ * uint32_t(o.repeats)), o.mean, o.contrast});
            const long long pairs = 2ll * std::max(0, o.size - w) * o.size;
            r.table.add({TableCell::integer(w), TableCell::value(c, "%g"),
                         TableCell::value(blendAlphaForCorrelation(c), "%.4f"),
                         TableCell::value(tileToTileCorrelation(s, w), "%.4f"), TableCell::integer(pairs)});
            rows.back().push_back(s);
            captions.back().push_back("w = " + std::to_string(w) + ", correlation " + TableCell::value(c, "%g").text);
        }
    }
    r.sheet = {"stimuli.png", sheet(rows, captions),
               "One stimulus per tile size w (rows) and tile-to-tile correlation (columns), as the experiment "
               "shows them (display values, " +
                   std::to_string(o.size) + " pixels, mean " + TableCell::value(o.mean, "%g").text +
                   "): tiled white noise blended with fresh noise by α and "
                   "contrast-corrected (eq. 2.24), correlation α²/(α² + (1 − α)²) (eq. 2.28)."};
    return r;
}

Report stimulusSetReport(const StimulusSet& set) {
    Report report =
        sectionReport("Perception experiment: the stimuli", {{"stimuli.csv", set.listing, false}}, set.images,
                      "<p><a href='experiment.html'>experiment.html</a> runs the experiment in a browser "
                      "(every stimulus is in the file); the stimuli command's analysis turns its answers "
                      "into detection rates (docs/EXPERIMENT.md).</p>");
    report.sections.front().files = {{"experiment.html", set.page, kExperimentTitle}};
    return report;
}

Report stimulusOverviewReport(const StimulusOverview& overview, const StimulusSet& set) {
    Report report =
        sectionReport("Perception stimuli (Figures 2.13–2.14)", {{"overview.csv", overview.table}}, {overview.sheet});
    report.sections.front().files = {{"experiment.html", set.page, kExperimentTitle}};
    return report;
}

}  // namespace stochtex
