// The perception stimuli and experiment (thesis §2.6.2): the stimuli's
// display values and measured tile-to-tile correlation, the seeded trial
// order and page, and the detection rates of an answers file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <string>

#include "stochtex/analysis/binomial.h"
#include "stochtex/core/error.h"
#include "stochtex/core/parallel.h"
#include "stochtex/noise/tiled_white_noise.h"
#include "stochtex/studies/stimuli.h"
#include "stochtex/studies/stimuli_analysis.h"

namespace stochtex {
namespace {

std::string parameterOf(const StimulusSetOptions& o) {
    try {
        validateStimulusSet(o);
    } catch (const InputError& e) {
        return e.parameter();
    }
    return "(none)";
}

TEST(Stimuli, DisplayValuesKeepMeanAndContrastWithoutClipping) {
    // One tile per image (w = size): i.i.d. pixels, N = 256². Mean ± 5σ/√N;
    // standard deviation a/√3 ± 5 % (the sample variance's relative deviation
    // is below √(2/N) = 0.0055, so 5 % only guards the amplitude's formula).
    for (double mean : {0.5, 0.3}) {
        const double a = stimulusAmplitude(mean, 1.0);
        EXPECT_NEAR(a, std::min(mean, 1.0 - mean) / std::sqrt(2.0), 1e-15);
        const Image s = stimulusImage({256, 256, 0.5, 3, mean, 1.0});  // α = ½: the widest range, mean ± a√2
        double sum = 0, sum2 = 0, lo = 1, hi = 0;
        for (float v : s.data())
            sum += v, sum2 += double(v) * v, lo = std::min(lo, double(v)), hi = std::max(hi, double(v));
        const double n = double(s.data().size()), m = sum / n, sd = std::sqrt(sum2 / n - m * m);
        EXPECT_NEAR(m, mean, 5.0 * (a / std::sqrt(3.0)) / std::sqrt(n)) << mean;
        EXPECT_NEAR(sd, a / std::sqrt(3.0), 0.05 * a / std::sqrt(3.0)) << mean;
        EXPECT_GE(lo, mean - a * std::sqrt(2.0) - 1e-6);
        EXPECT_LE(hi, mean + a * std::sqrt(2.0) + 1e-6);
        EXPECT_GT(lo, 0.0);
        EXPECT_LT(hi, 1.0);
    }
}

TEST(Stimuli, EightBitStimuliHaveTheRequestedTileToTileCorrelation) {
    // What the viewer sees: the 8-bit codes (quantisation adds a variance of
    // 1/12 code², 3·10⁻⁵ of the noise's). Pairs one tile apart in 16 images of
    // 128² with w = 64: N = 65536 independent pairs; tolerance 5 (1 − ρ²)/√N
    // (see TiledWhiteNoise.MeasuredTileToTileCorrelationIsEq228).
    for (double c : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        double n = 0, sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
        for (uint32_t seed = 0; seed < 16; ++seed) {
            const Image s = stimulusImage({128, 64, c, 77 + seed, 0.5, 1.0});
            for (int y = 0; y < 64; ++y)
                for (int x = 0; x < 64; ++x) {
                    const double a = std::lround(255.0 * s.at(x, y)), b = std::lround(255.0 * s.at(x + 64, y));
                    n += 1, sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b;
                }
        }
        const double ma = sa / n, mb = sb / n;
        const double r = (sab / n - ma * mb) / std::sqrt((saa / n - ma * ma) * (sbb / n - mb * mb));
        EXPECT_NEAR(r, c, 5.0 * (1.0 - c * c) / std::sqrt(n) + 1e-6) << c;
        std::printf("8-bit stimuli, c = %.2f (alpha %.4f): measured %.4f\n", c, blendAlphaForCorrelation(c), r);
    }
}

TEST(Stimuli, TrialOrderIsASeededPermutation) {
    const std::vector<int> a = stimulusTrialOrder(30, 5), b = stimulusTrialOrder(30, 5), c = stimulusTrialOrder(30, 6);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    std::vector<int> sorted = a;
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < 30; ++i) EXPECT_EQ(sorted[i], i);
    // Uniform: where item 0 lands over 2000 seeds, 10 places, 200 ± 5·√(200·0.9) each.
    std::vector<int> where(10, 0);
    for (uint32_t seed = 0; seed < 2000; ++seed) {
        const std::vector<int> o = stimulusTrialOrder(10, seed);
        where[std::find(o.begin(), o.end(), 0) - o.begin()]++;
    }
    for (int k = 0; k < 10; ++k) EXPECT_NEAR(where[k], 200, 5.0 * std::sqrt(200 * 0.9)) << k;
}

TEST(Stimuli, SetListsEveryStimulusOnceInTheSeededOrderAndEmbedsThemInThePage) {
    StimulusSetOptions o;
    o.size = 16;
    o.tiles = {4, 8};
    o.correlations = {0, 0.5, 1};
    o.repeats = 2;
    o.seed = 9;
    StimulusSet one, two;
    {
        ThreadLimit limit(1);
        one = stimulusSet(o);
    }
    {
        ThreadLimit limit(2);
        two = stimulusSet(o);
    }
    ASSERT_EQ(one.trials.size(), 12u);
    ASSERT_EQ(one.images.size(), 12u);
    EXPECT_EQ(one.listing.rows.size(), 12u);
    EXPECT_EQ(one.page, two.page);
    std::set<std::string> names;
    for (size_t i = 0; i < one.trials.size(); ++i) {
        const StimulusTrial& t = one.trials[i];
        EXPECT_EQ(t.trial, int(i) + 1);
        EXPECT_EQ(one.images[i].file, t.stimulus);
        EXPECT_TRUE(one.images[i].image.data() == two.images[i].image.data());
        EXPECT_NEAR(t.alpha, blendAlphaForCorrelation(t.correlation), 1e-15);
        names.insert(t.stimulus);
        EXPECT_NE(one.page.find("\"stimulus\":\"" + t.stimulus + "\""), std::string::npos) << t.stimulus;
    }
    EXPECT_EQ(names.size(), 12u);
    // The order is the seed's: another seed, another order (and images).
    o.seed = 10;
    const StimulusSet other = stimulusSet(o);
    std::vector<std::string> a, b;
    for (const auto& t : one.trials) a.push_back(t.stimulus);
    for (const auto& t : other.trials) b.push_back(t.stimulus);
    EXPECT_NE(a, b);
    // Trial 1 of the page is the first image, embedded as a PNG data: URI.
    EXPECT_NE(
        one.page.find("<img id='stimulus-1' class='stimulus' alt='' src='" + pngDataUri(one.images[0].image) + "'>"),
        std::string::npos);
    EXPECT_NE(one.page.find("background:rgb(128,128,128)"), std::string::npos);  // mean ½ → code 128
}

TEST(Stimuli, SetRefusesBadParametersByName) {
    StimulusSetOptions o;
    o.size = 64;
    EXPECT_EQ(parameterOf(o), "(none)");
    auto with = [&](auto change) {
        StimulusSetOptions c = o;
        change(c);
        return parameterOf(c);
    };
    EXPECT_EQ(with([](auto& c) { c.tiles = {24}; }), "tiles");  // does not divide 64
    EXPECT_EQ(with([](auto& c) { c.tiles = {0}; }), "tiles");
    EXPECT_EQ(with([](auto& c) { c.tiles = {8, 8}; }), "tiles");
    EXPECT_EQ(with([](auto& c) { c.correlations = {0.5, 1.5}; }), "correlations");
    EXPECT_EQ(with([](auto& c) { c.correlations = {}; }), "correlations");
    EXPECT_EQ(with([](auto& c) { c.repeats = 0; }), "repeats");
    EXPECT_EQ(with([](auto& c) { c.size = 4; }), "size");
    EXPECT_EQ(with([](auto& c) { c.mean = 1.0; }), "mean");
    EXPECT_EQ(with([](auto& c) { c.contrast = 0.0; }), "contrast");
    EXPECT_EQ(with([](auto& c) { c.durationMs = 0; }), "durationMs");
    EXPECT_EQ(with([](auto& c) { c.resetMs = -1; }), "resetMs");
    EXPECT_EQ(with([](auto& c) { c.repeats = 1000, c.tiles = {1, 2, 4, 8, 16, 32}; }), "repeats");  // 30000 trials
}

TEST(StimuliAnalysis, RatesAndWilsonIntervalsOfKnownCounts) {
    // w = 8, c = 0: 0 of 4 yes; w = 8, c = 1: 3 of 4; w = 16, c = 0.5: 1 of 2; w = 16, c = 1: 5 of 5.
    std::string csv = "trial,stimulus,w,correlation,alpha,answer,response_time_ms,shown_ms\r\n";
    int trial = 0;
    auto add = [&](int w, const char* c, const char* answer) {
        csv += std::to_string(++trial) + ",s.png," + std::to_string(w) + "," + c + ",0.5," + answer + ",500,1000\r\n";
    };
    for (int i = 0; i < 4; ++i) add(8, "0", "no");
    for (const char* a : {"yes", "Y", "yes", "no"}) add(8, "1", a);
    add(16, "0.5", "yes");
    add(16, "0.50", "n");
    for (int i = 0; i < 5; ++i) add(16, "1", "yes");
    csv += "\n";
    const DetectionRates r = detectionRates(parseStimulusAnswers(csv, "answers.csv"));
    // Hand-computed Wilson bounds, z = 1.959964: k = 0 → [0, z²/(n + z²)];
    // k = n → [n/(n + z²), 1]; 3/4 → [0.300642, 0.954413]; 1/2 → [0.094531, 0.905469].
    const double z2 = kZ95 * kZ95;
    struct Row {
        double w, c, trials, yes, rate, low, high;
    };
    const Row expected[] = {{8, 0, 4, 0, 0.0, 0.0, z2 / (4 + z2)},
                            {8, 1, 4, 3, 0.75, 0.300642, 0.954413},
                            {16, 0.5, 2, 1, 0.5, 0.094531, 0.905469},
                            {16, 1, 5, 5, 1.0, 5 / (5 + z2), 1.0}};
    ASSERT_EQ(r.table.rows.size(), 4u);
    for (size_t i = 0; i < 4; ++i) {
        const auto& row = r.table.rows[i];
        const Row& e = expected[i];
        const double got[] = {*row[0].number, *row[1].number, *row[2].number, *row[3].number,
                              *row[4].number, *row[5].number, *row[6].number};
        const double want[] = {e.w, e.c, e.trials, e.yes, e.rate, e.low, e.high};
        for (int k = 0; k < 7; ++k)
            EXPECT_NEAR(got[k], want[k], 1e-6) << "row " << i << " column " << k;  // 1e-6: 6 digits by hand
    }
    EXPECT_EQ(r.table.csv().substr(0, r.table.csv().find('\n')), "w,correlation,trials,yes,rate,ci_low,ci_high");
    // detection.png and one plot per w.
    ASSERT_EQ(r.figures.size(), 3u);
    EXPECT_EQ(r.figures[0].file, "detection.png");
    EXPECT_EQ(r.figures[1].file, "detection_w8.png");
    EXPECT_EQ(r.figures[2].file, "detection_w16.png");
    ASSERT_TRUE(r.figures[0].chart);
    EXPECT_EQ(r.figures[0].chart->series.size(), 2u);
}

TEST(StimuliAnalysis, BadAnswersNameTheFileAndLine) {
    auto message = [](const std::string& text) {
        try {
            parseStimulusAnswers(text, "answers.csv");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("(no error)");
    };
    const std::string header = "trial,w,correlation,answer\n";
    EXPECT_EQ(message(""), "answers.csv: empty file (expected a header line naming w, correlation, answer)");
    EXPECT_EQ(message(header), "answers.csv: no answers (only a header line)");
    EXPECT_EQ(message("trial,w,correlation\n1,8,0.5\n"),
              "answers.csv:1: no column \"answer\" (the header needs w, correlation and answer)");
    EXPECT_EQ(message(header + "1,8,0.5,yes\n2,8,0.5,maybe\n"),
              "answers.csv:3: answer must be yes or no, got \"maybe\"");
    EXPECT_EQ(message(header + "1,8,0.5\n"), "answers.csv:2: 3 fields, the header has 4");
    EXPECT_EQ(message(header + "\n1,x,0.5,no\n"), "answers.csv:3: w must be a positive integer, got \"x\"");
    EXPECT_EQ(message(header + "1,8,1.5,no\n"), "answers.csv:2: correlation must be a number in [0, 1], got \"1.5\"");
    EXPECT_EQ(message(header + "1,8,nan,no\n"), "answers.csv:2: correlation must be a number in [0, 1], got \"nan\"");
    EXPECT_EQ(message(header + "1,8,0.5,no\n"), "(no error)");
    EXPECT_EQ(message(header + "1,8,0.5,no\n" + header + "1,8,0.5,yes\n"), "(no error)");  // two files concatenated
    EXPECT_EQ(parseStimulusAnswers(header + "1,8,0.5,no\n" + header + "1,8,0.5,yes\n", "a.csv").size(), 2u);
    EXPECT_THROW(readStimulusAnswers("/nonexistent/answers.csv"), InputError);
}

// Read in blocks: a file longer than a block reads whole, a file at the
// limit is read and one byte past it refused, naming the file.
TEST(StimuliAnalysis, AnswersFilesAreReadWholeUpToTheLimit) {
    const std::string path = testing::TempDir() + "stimuli_answers_limit.csv";
    const std::string header = "trial,w,correlation,answer\n";
    const std::string line = "1,8,0.5,yes\n";
    auto write = [&](const std::string& text) { std::ofstream(path, std::ios::binary) << text; };
    std::string text = header;
    while (text.size() + line.size() <= 200000) text += line;  // three blocks and some
    write(text);
    EXPECT_EQ(readStimulusAnswers(path).size(), (text.size() - header.size()) / line.size());
    text.resize(kMaxAnswersBytes, '\n');  // blank lines are skipped
    write(text);
    EXPECT_EQ(readStimulusAnswers(path).size(), (200000 - header.size()) / line.size());
    write(text + "\n");
    try {
        readStimulusAnswers(path);
        ADD_FAILURE() << "a file one byte past the limit was read";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  path + ": more than 16777216 bytes; an answers file holds one short line a trial");
    }
    std::remove(path.c_str());
}

}  // namespace
}  // namespace stochtex

namespace stochtex {
namespace {

// The report's overview measures eq. 2.28 on the very images it shows:
// 2·(256 − w)·256 pixel pairs give a standard error near 0.003 for
// independent pairs; 0.03 leaves room for the pairs' dependence (each
// pixel is in up to four).
TEST(StimulusOverview, MeasuresTheAskedTileCorrelationOnTheImagesShown) {
    StimulusSetOptions o;
    o.tiles = {16, 32};
    o.correlations = {0, 0.5, 1};
    const StimulusOverview v = stimulusOverview(o);
    ASSERT_EQ(v.table.rows.size(), 6u);
    for (const auto& row : v.table.rows) {
        const double asked = row[1].number.value(), measured = row[3].number.value();
        EXPECT_NEAR(measured, asked, asked == 1 ? 1e-9 : 0.03) << row[0].text << " " << row[1].text;
        EXPECT_EQ(row[4].number.value(), 2.0 * (256 - row[0].number.value()) * 256);
    }
    EXPECT_EQ(v.sheet.file, "stimuli.png");
    EXPECT_GT(v.sheet.image.width(), 3 * 256);
    EXPECT_GT(v.sheet.image.height(), 2 * 256);
    // The measure itself: a checkerboard of 4-pixel squares repeats every 8
    // pixels (correlation 1) and flips every 4 (−1), along x and y.
    Image board(64, 64, 1);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) board.at(x, y) = float(((x % 8) < 4) != ((y % 8) < 4));
    EXPECT_NEAR(tileToTileCorrelation(board, 8), 1.0, 1e-12);
    EXPECT_NEAR(tileToTileCorrelation(board, 4), -1.0, 1e-12);
}

}  // namespace
}  // namespace stochtex
