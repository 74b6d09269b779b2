#include "stochtex/report/table.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace stochtex {

TableCell TableCell::value(double v, const char* format) {
    char b[64];
    std::snprintf(b, sizeof b, format, v);
    TableCell c(b);
    c.number = v;
    return c;
}

TableCell TableCell::integer(long long v) {
    TableCell c(std::to_string(v));
    c.number = double(v);
    return c;
}

TableCell TableCell::none() {
    TableCell c("—");
    c.number = std::numeric_limits<double>::quiet_NaN();  // written as an empty CSV field
    return c;
}

TableCell TableCell::percent(double v, int decimals) {
    const double step = std::pow(10.0, -decimals);
    char b[64];
    if (v > 0 && v < step)
        std::snprintf(b, sizeof b, "< %.*f", decimals, step);
    else if (v < 100 && v > 100 - step)
        std::snprintf(b, sizeof b, "> %.*f", decimals, 100 - step);
    else
        std::snprintf(b, sizeof b, "%.*f", decimals, v);
    TableCell c(b);
    c.number = v;
    return c;
}

void Table::add(std::vector<TableCell> row) {
    if (row.size() != columns.size())
        throw std::logic_error("table row has " + std::to_string(row.size()) + " cells for " +
                               std::to_string(columns.size()) + " columns");
    rows.push_back(std::move(row));
}

namespace {

std::string headerText(const TableColumn& c) { return c.unit.empty() ? c.header : c.header + " (" + c.unit + ")"; }

}  // namespace

std::string Table::csv() const {
    std::ostringstream o;
    for (size_t i = 0; i < columns.size(); ++i) o << (i ? "," : "") << columns[i].key;
    o << '\n';
    for (const auto& row : rows) {
        for (size_t i = 0; i < row.size(); ++i) {
            o << (i ? "," : "");
            if (row[i].number && std::isnan(*row[i].number)) continue;  // none(): an empty field
            if (row[i].number) o << *row[i].number;
            else o << row[i].text;
        }
        o << '\n';
    }
    return o.str();
}

namespace {

// A cell's text inside a Markdown table: a '|' would end the cell (|ΔI|).
std::string markdownCell(const std::string& text) {
    std::string out;
    for (char ch : text) {
        if (ch == '|') out += '\\';
        out += ch;
    }
    return out;
}

}  // namespace

std::string Table::markdown() const {
    std::ostringstream o;
    if (!title.empty()) o << "**" << title << "**" << (note.empty() ? "" : " " + note) << "\n\n";
    o << '|';
    for (const auto& c : columns) o << ' ' << markdownCell(headerText(c)) << " |";
    o << "\n|";
    for (size_t i = 0; i < columns.size(); ++i) o << "---|";
    o << '\n';
    for (const auto& row : rows) {
        o << '|';
        for (const auto& c : row) o << ' ' << markdownCell(c.text) << " |";
        o << '\n';
    }
    return o.str();
}

std::string Table::html() const {
    std::ostringstream o;
    if (!title.empty()) {
        o << "<p><b>" << htmlEscape(title) << "</b>";
        if (!note.empty()) o << ' ' << htmlEscape(note);
        o << "</p>\n";
    }
    o << "<table><tr>";
    for (const auto& c : columns) o << "<th>" << htmlEscape(headerText(c)) << "</th>";
    o << "</tr>";
    for (const auto& row : rows) {
        o << "<tr>";
        for (const auto& c : row) o << "<td>" << htmlEscape(c.text) << "</td>";
        o << "</tr>";
    }
    o << "</table>\n";
    return o.str();
}

std::string htmlEscape(const std::string& s) {
    std::string o;
    for (char c : s) {
        if (c == '<') o += "&lt;";
        else if (c == '>') o += "&gt;";
        else if (c == '&') o += "&amp;";
        else o += c;
    }
    return o;
}

}  // namespace stochtex
