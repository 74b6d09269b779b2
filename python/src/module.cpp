// The Python module stochtex._stochtex (issue 35): the library's patterns,
// renderers, footprint statistics and studies over numpy arrays. The
// package stochtex (python/stochtex/__init__.py) re-exports it and adds
// what is easier written in Python (a dict as a pattern, Table).
//
// Errors: an InputError of the library (a bad file, a parameter out of its
// range) raises stochtex.InputError, a ValueError whose message is the
// library's (the CLI prints the same after its flag) and whose `parameter`
// is the library's parameter name in snake case, the keyword that sets it
// ("tiltDeg" → tilt_deg; None for an error about no one parameter: a file
// or JSON value, whose message names the file and JSON pointer, a path); GpuUnavailable raises
// stochtex.GpuUnavailable (a RuntimeError).
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "bindings.h"
#include "stochtex/core/error.h"
#include "stochtex/gpu/gl_context.h"
#include "stochtex/pattern/param_info.h"

namespace stochtex::python {

std::string keywordOf(const std::string& parameter) {
    std::string k = kebabCase(parameter);  // the CLI's flag spelling, with underscores
    std::replace(k.begin(), k.end(), '-', '_');
    // A Python keyword cannot be written as an argument's name: PEP 8's
    // trailing underscore (the stability study's "from" is from_).
    static const std::set<std::string> reserved{
        "False", "None",     "True",  "and",    "as",   "assert", "async",  "await",    "break",
        "class", "continue", "def",   "del",    "elif", "else",   "except", "finally",  "for",
        "from",  "global",   "if",    "import", "in",   "is",     "lambda", "nonlocal", "not",
        "or",    "pass",     "raise", "return", "try",  "while",  "with",   "yield"};
    if (reserved.count(k)) k += '_';
    return k;
}

py::tuple tableTuple(const Table& table) {
    py::list columns;
    for (size_t c = 0; c < table.columns.size(); ++c) {
        bool numeric = true;
        for (const auto& row : table.rows)
            numeric = numeric && (row[c].number || row[c].text == TableCell::none().text);
        py::object values;
        if (numeric) {
            std::vector<double> v;
            v.reserve(table.rows.size());
            for (const auto& row : table.rows) v.push_back(row[c].number ? *row[c].number : std::nan(""));
            values = ownedArray<double>(std::move(v), {py::ssize_t(table.rows.size())});
        } else {
            py::list text;
            for (const auto& row : table.rows) text.append(row[c].text);
            values = std::move(text);
        }
        const TableColumn& col = table.columns[c];
        columns.append(py::make_tuple(col.key, col.header, col.unit, values));
    }
    return py::make_tuple(table.title, table.note, columns);
}

Progress pythonProgress(const py::object& callback) {
    return [callback](double fraction, const std::string& step) {
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        if (!callback.is_none()) callback(fraction, step);
    };
}

py::dict reportDict(Report&& report) {
    py::list sections;
    for (ReportSection& section : report.sections) {
        py::list tables, figures;
        for (const ReportTable& t : section.tables) tables.append(py::make_tuple(t.file, tableTuple(t.table)));
        for (Figure& f : section.figures)
            figures.append(py::make_tuple(f.file, f.caption, imageArray(std::move(f.image))));
        py::dict d;
        d["heading"] = section.heading;
        d["html"] = section.html;
        d["tables"] = tables;
        d["figures"] = figures;
        py::dict files;
        for (const ReportFile& f : section.files) files[py::str(f.file)] = f.text;
        d["files"] = files;
        d["folder"] = section.folder;
        sections.append(d);
    }
    py::dict d;
    d["title"] = report.title;
    d["sections"] = sections;
    return d;
}

}  // namespace stochtex::python

PYBIND11_MODULE(_stochtex, m) {
    namespace py = pybind11;
    using namespace stochtex;
    m.doc() = "stochtex: colour-mapped noise vector fields, filtered, and the studies of their artifacts";

    static py::exception<InputError> inputError(m, "InputError", PyExc_ValueError);
    static py::exception<GpuUnavailable> gpuUnavailable(m, "GpuUnavailable", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const InputError& e) {
            py::object error = py::reinterpret_borrow<py::object>(inputError.ptr())(e.what());
            error.attr("parameter") =
                e.parameter().empty() ? py::none() : py::object(py::str(python::keywordOf(e.parameter())));
            PyErr_SetObject(inputError.ptr(), error.ptr());
        } catch (const GpuUnavailable& e) {
            gpuUnavailable(e.what());
        }
    });

    python::bindImages(m);
    python::bindSources(m);
    python::bindPatterns(m);
    python::bindShadertoy(m);
    python::bindStudies(m);
}
