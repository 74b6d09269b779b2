#include "stochtex/studies/stimuli_analysis.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "stochtex/analysis/binomial.h"
#include "stochtex/core/budget.h"
#include "stochtex/core/error.h"
#include "stochtex/report/plot.h"

namespace stochtex {

namespace {

std::string trim(std::string s) {
    while (!s.empty() && (s.back() == '\r' || s.back() == ' ' || s.back() == '\t')) s.pop_back();
    size_t i = 0;
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    s.erase(0, i);
    if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
    return s;
}

std::vector<std::string> fields(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream in(line);
    std::string f;
    while (std::getline(in, f, ',')) out.push_back(trim(f));
    if (!line.empty() && line.back() == ',') out.push_back("");
    return out;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// The tile-size series' colours: Okabe–Ito, distinguishable by most readers.
constexpr std::array<std::array<float, 3>, 7> kColours{{{0.0f, 0.45f, 0.70f},
                                                        {0.84f, 0.37f, 0.0f},
                                                        {0.0f, 0.62f, 0.45f},
                                                        {0.80f, 0.47f, 0.65f},
                                                        {0.34f, 0.71f, 0.91f},
                                                        {0.90f, 0.62f, 0.0f},
                                                        {0.2f, 0.2f, 0.2f}}};

}  // namespace

std::vector<StimulusAnswer> parseStimulusAnswers(const std::string& text, const std::string& source) {
    std::stringstream in(text);
    std::string line;
    int number = 0;
    std::vector<std::string> header;
    while (header.empty() && std::getline(in, line)) {
        ++number;
        if (!trim(line).empty()) header = fields(line);
    }
    if (header.empty())
        throw InputError(source + ": empty file (expected a header line naming w, correlation, answer)");
    const int headerLine = number;
    auto column = [&](const std::string& name) {
        for (size_t i = 0; i < header.size(); ++i)
            if (lower(header[i]) == name) return int(i);
        throw InputError(source + ":" + std::to_string(headerLine) + ": no column \"" + name +
                         "\" (the header needs w, correlation and answer)");
    };
    const int cw = column("w"), cc = column("correlation"), ca = column("answer");
    std::vector<StimulusAnswer> answers;
    while (std::getline(in, line)) {
        ++number;
        // Blank lines, and the header again where participants' files were concatenated.
        if (trim(line).empty() || fields(line) == header) continue;
        const std::string at = source + ":" + std::to_string(number) + ": ";
        const std::vector<std::string> f = fields(line);
        if (f.size() != header.size())
            throw InputError(at + std::to_string(f.size()) + " fields, the header has " +
                             std::to_string(header.size()));
        StimulusAnswer a;
        char* end = nullptr;
        errno = 0;
        const long w = std::strtol(f[cw].c_str(), &end, 10);
        if (f[cw].empty() || *end != '\0' || errno != 0 || w < 1 || w > 1 << 20)
            throw InputError(at + "w must be a positive integer, got \"" + f[cw] + "\"");
        a.tile = int(w);
        a.correlation = std::strtod(f[cc].c_str(), &end);
        if (f[cc].empty() || *end != '\0' || !(a.correlation >= 0.0 && a.correlation <= 1.0))
            throw InputError(at + "correlation must be a number in [0, 1], got \"" + f[cc] + "\"");
        const std::string answer = lower(f[ca]);
        if (answer == "yes" || answer == "y")
            a.yes = true;
        else if (answer != "no" && answer != "n")
            throw InputError(at + "answer must be yes or no, got \"" + f[ca] + "\"");
        answers.push_back(a);
    }
    if (answers.empty()) throw InputError(source + ": no answers (only a header line)");
    std::set<int> tiles;
    for (const StimulusAnswer& a : answers) tiles.insert(a.tile);
    if ((long long)tiles.size() > budgeted(kMaxAnswerTileSizes))
        throw InputError::overBudget("", source + ": answers for " + std::to_string(tiles.size()) +
                                             " tile sizes; at most " + std::to_string(budgeted(kMaxAnswerTileSizes)) +
                                             " are analysed (each is a plot)");
    return answers;
}

std::vector<StimulusAnswer> readStimulusAnswers(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot read the answers file");
    // Read in blocks up to one byte past the limit, which tells a file at the
    // limit from a larger one without reading the rest (a device may never
    // end) and without a buffer of the limit's size for a short file.
    std::string text;
    std::array<char, 1 << 16> block;
    while (in.read(block.data(), std::streamsize(block.size())) || in.gcount() > 0) {
        text.append(block.data(), size_t(in.gcount()));
        if (text.size() > kMaxAnswersBytes)
            throw InputError(path + ": more than " + std::to_string(kMaxAnswersBytes) +
                             " bytes; an answers file holds one short line a trial");
    }
    if (in.bad()) throw InputError(path + ": cannot read the answers file");
    return parseStimulusAnswers(text, path);
}

DetectionRates detectionRates(const std::vector<StimulusAnswer>& answers) {
    std::map<int, std::map<double, std::pair<int, int>>> counts;  // w → correlation → (yes, trials)
    for (const StimulusAnswer& a : answers) {
        auto& c = counts[a.tile][a.correlation];
        c.first += a.yes;
        c.second += 1;
    }
    DetectionRates r;
    r.table.title = "Detection rate";
    r.table.note = "(fraction of \"yes, a repeating pattern\" per tile size and correlation; 95 % Wilson interval)";
    r.table.columns = {{"w", "tile size w", "pixels"}, {"correlation", "correlation", ""},
                       {"trials", "trials", ""},       {"yes", "yes", ""},
                       {"rate", "detection rate", ""}, {"ci_low", "95 % low", ""},
                       {"ci_high", "95 % high", ""}};
    std::vector<PlotSeries> overview;
    std::vector<Figure> perTile;
    LinePlotOptions lo;
    lo.xLabel = "tile-to-tile correlation";
    lo.yLabel = "detection rate";
    lo.xMin = 0;
    lo.xMax = 1;
    lo.yMin = 0;
    lo.yMax = 1;
    for (const auto& [w, byCorrelation] : counts) {
        const auto colour = kColours[overview.size() % kColours.size()];
        PlotSeries rate{"w = " + std::to_string(w), {}, {}, colour};
        PlotSeries low{"95 % interval, low", {}, {}, {0.55f, 0.55f, 0.55f}};
        PlotSeries high{"95 % interval, high", {}, {}, {0.55f, 0.55f, 0.55f}};
        for (const auto& [c, yesTrials] : byCorrelation) {
            const Proportion p = wilsonInterval(yesTrials.first, yesTrials.second);
            r.table.add({TableCell::integer(w), TableCell::value(c, "%g"), TableCell::integer(yesTrials.second),
                         TableCell::integer(yesTrials.first), TableCell::value(p.rate, "%.3f"),
                         TableCell::value(p.low, "%.3f"), TableCell::value(p.high, "%.3f")});
            for (PlotSeries* s : {&rate, &low, &high}) s->x.push_back(c);
            rate.y.push_back(p.rate);
            low.y.push_back(p.low);
            high.y.push_back(p.high);
        }
        overview.push_back(rate);
        LinePlotOptions one = lo;
        one.title = "Detection rate, w = " + std::to_string(w) + " pixels";
        const std::vector<PlotSeries> series{rate, low, high};
        perTile.push_back(chartFigure("detection_w" + std::to_string(w) + ".png", {series, one},
                                      "Tile size w = " + std::to_string(w) +
                                          ": fraction of yes over correlation, with the 95 % "
                                          "Wilson interval."));
    }
    lo.title = "Detection rate per tile size";
    r.figures.push_back(
        chartFigure("detection.png", {overview, lo},
                    "Fraction of \"yes, a repeating pattern\" over the tile-to-tile correlation, one line per "
                    "tile size w."));
    r.figures.insert(r.figures.end(), perTile.begin(), perTile.end());
    return r;
}

Report detectionReport(const DetectionRates& r, const std::string& answers) {
    Report report = sectionReport("Perception experiment: detection rates", {{"detection.csv", r.table}}, r.figures,
                                  "<p>Answers: " + htmlEscape(answers) + "</p>");
    report.sections.front().files = {{"detection.md", r.table.markdown(), ""}};
    return report;
}

}  // namespace stochtex
