#pragma once
// A study's report as a value: a title, sections of text, tables and
// figures. Studies return it (they never write files); one function writes
// any report into a folder with its index.html, and `reproduce all` and
// `analyze` are reports merged from their parts'.
#include <cstddef>
#include <string>
#include <vector>

#include "stochtex/report/page.h"
#include "stochtex/report/table.h"

namespace stochtex {

// A table of a section: written as `file` (CSV) when named, and shown on the
// page unless `onPage` is false (a per-frame table is only a CSV).
struct ReportTable {
    std::string file;
    Table table;
    bool onPage = true;
};

// Any other text file of a section (a Markdown table), or a page of its
// own (an experiment): with a pageTitle, text is the body htmlPage frames.
struct ReportFile {
    std::string file;
    std::string text;
    std::string pageTitle;
};

// A video the caller wrote into the section's folder (FrameSequenceWriter:
// name.mp4 and its animated preview name.webp), shown by its preview.
struct ReportVideo {
    std::string name;
    std::string caption;  // HTML
};

struct ReportSection {
    std::string heading;  // HTML-escaped; empty: none
    int level = 2;        // <h2>; a merged part's own sections go one deeper
    std::string html;     // paragraphs under the heading, before the tables (HTML)
    // Where its files go, relative to the report's folder ("": the folder
    // itself); the page links to them there.
    std::string folder;
    std::vector<ReportTable> tables;
    std::vector<ReportVideo> videos;  // shown after the tables
    std::vector<Figure> figures;      // every one is written; the captioned ones are shown
    size_t figuresShown = SIZE_MAX;
    std::string htmlAfter;  // after the figures (HTML): links, figures of other kinds
    std::vector<ReportFile> files;
};

struct Report {
    std::string title;  // the page's <title> and <h1> (HTML-escaped)
    std::string html;   // paragraphs under the title (HTML)
    std::vector<ReportSection> sections;
    int maxWidthPx = 1200, captionWidthPx = 560;  // htmlPage's
};

// A report of one untitled section: the usual shape of one study's.
Report sectionReport(std::string title, std::vector<ReportTable> tables, std::vector<Figure> figures,
                     std::string html = "");

// index.html's text: the title, then each section's heading, text, tables
// and figures (linked in the section's folder).
std::string reportPage(const Report& report);

// Writes index.html alone (the sections' files written before, e.g. part by
// part as a long run goes).
void writeReportPage(const std::string& folder, const Report& report);

// Writes each section's figures, named tables (CSV) and files into
// folder/<section folder> (creating it), then folder/index.html; returns the
// files written, relative to folder, in that order. A file that two sections
// name in one folder (a figure shown twice) is written once, the first's.
std::vector<std::string> writeReport(const std::string& folder, const Report& report);

// Appends `part`'s sections to `into` with their files under `folder`
// (relative to into's folder), led by `heading` (else part's title) and
// `html` then part's own text: the first section takes them when it has no
// heading of its own. The part's own headings go one level deeper.
void appendReport(Report& into, Report part, const std::string& folder, const std::string& heading = "",
                  const std::string& html = "");

// "a, b and c": the files a command names after writing a report.
std::string listNames(const std::vector<std::string>& names);

}  // namespace stochtex
