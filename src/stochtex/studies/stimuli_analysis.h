#pragma once
// The answers of the perception experiment (stimuli.h, the CSV its page
// offers) turned into detection rates: the fraction of "yes" (repeating
// pattern seen) per tile size w and correlation, with 95 % Wilson score
// intervals (analysis/binomial.h), as a table and plots over correlation.
#include <string>
#include <vector>

#include "stochtex/report/page.h"
#include "stochtex/report/report.h"
#include "stochtex/report/table.h"

namespace stochtex {

struct StimulusAnswer {
    int tile = 0;  // w
    double correlation = 0;
    bool yes = false;
};

// The answers CSV: a header line naming at least the columns w, correlation
// and answer (any order; others, e.g. trial, stimulus, alpha,
// response_time_ms, are ignored), then one line per trial: w a positive
// integer, correlation in [0, 1], answer yes or no (also y / n, any case).
// Blank lines, CR line ends and repeats of the header line (files
// concatenated) are allowed, fields may be "quoted". A bad
// file is one InputError "SOURCE:LINE: problem" (SOURCE alone for an empty
// file or one without answers).
// Answers for more than kMaxAnswerTileSizes tile sizes are refused (each
// is a plot of the report: 200 of them took 1.6 GB).
constexpr int kMaxAnswerTileSizes = 32;
std::vector<StimulusAnswer> parseStimulusAnswers(const std::string& text, const std::string& source);
// The same from a file of at most kMaxAnswersBytes (a trial is one short
// line: 16 MiB holds 10⁵ participants' sessions of kMaxStimulusTrials);
// InputError naming it when it cannot be read or is larger (/dev/zero as
// the file ended in bad_alloc).
constexpr size_t kMaxAnswersBytes = size_t(16) << 20;
std::vector<StimulusAnswer> readStimulusAnswers(const std::string& path);

struct DetectionRates {
    // detection.csv: w, correlation, trials, yes, rate, ci_low, ci_high; by w,
    // then correlation.
    Table table;
    // detection.png: the rate over correlation, one line per w; then
    // detection_w<w>.png per w: its rate with the interval's bounds.
    std::vector<Figure> figures;
};
DetectionRates detectionRates(const std::vector<StimulusAnswer>& answers);
// Its report: detection.csv, detection.md and the plots; `answers` names the
// answers file.
Report detectionReport(const DetectionRates& rates, const std::string& answers);

}  // namespace stochtex
