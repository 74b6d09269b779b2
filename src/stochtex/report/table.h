#pragma once
// One table for every study: columns with a header and a unit, rows of
// cells, rendered to CSV (machine keys, raw numbers), Markdown and HTML
// (headers, formatted text). Nothing is rendered to one format and parsed
// back into another.
#include <optional>
#include <string>
#include <vector>

namespace stochtex {

struct TableColumn {
    std::string key;     // CSV header (snake_case)
    std::string header;  // Markdown / HTML header
    std::string unit;    // shown as "header (unit)" when not empty
};

struct TableCell {
    std::string text;              // as shown in Markdown / HTML
    std::optional<double> number;  // written to CSV at full default precision when set, else text
    TableCell() = default;
    TableCell(std::string t) : text(std::move(t)) {}
    TableCell(const char* t) : text(t) {}
    // A number shown with a printf format (e.g. "%.4f").
    static TableCell value(double v, const char* format = "%.4f");
    static TableCell integer(long long v);
    // A cell that does not apply to its row: "—" on pages, empty in CSV.
    static TableCell none();
    // A percentage with `decimals` decimals that never rounds to 0 or 100
    // when it is not (99.998 → "> 99.99", 0.001 → "< 0.01").
    static TableCell percent(double v, int decimals = 2);
};

struct Table {
    std::string title;  // bold line above the table (Markdown, HTML); may be empty
    std::string note;   // plain text after the title
    std::vector<TableColumn> columns;
    std::vector<std::vector<TableCell>> rows;

    // Appends a row; std::logic_error if its size differs from the columns'.
    void add(std::vector<TableCell> row);

    std::string csv() const;       // key line, then one line per row
    std::string markdown() const;  // title line (if any), header row, |---| line, rows
    std::string html() const;      // <p><b>title</b> note</p><table>…</table>, escaped
};

// <, > and & as HTML entities.
std::string htmlEscape(const std::string& s);

}  // namespace stochtex
