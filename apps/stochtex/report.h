#pragma once
// Pieces of the HTML report pages (`analyze`, `reproduce all`): figures with
// captions, Markdown tables as HTML, output folders.
#include <string>
#include <vector>

namespace stochtex::cli {

// One output of a study: a file in its folder and what it shows.
struct Figure {
    std::string file, caption;
};

// Creates dir (and parents); InputError if that fails.
void ensureFolder(const std::string& dir);

// <figure> elements linking to prefix + file.
std::string htmlFigures(const std::string& prefix, const std::vector<Figure>& figures, size_t limit = SIZE_MAX);

// The Markdown this project writes — "| a | b |" table rows (the first is the
// header, "|---" lines are skipped) and "**bold** text" lines — as HTML.
std::string markdownToHtml(const std::string& md);

}  // namespace stochtex::cli
