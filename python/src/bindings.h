#pragma once
// What the Python module's binding files share: numpy arrays made from the
// library's values without copying, and the conversion of a report's table.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <tbb/task_arena.h>

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "stochtex/core/error.h"
#include "stochtex/core/progress.h"
#include "stochtex/image/colour_space.h"
#include "stochtex/image/image.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/report/report.h"
#include "stochtex/report/table.h"
#include "stochtex/textures/texture_source.h"

namespace stochtex::python {

namespace py = pybind11;

// `values` moved into a numpy array of `shape` (C order) that owns it: no copy.
template <class T, class Buffer>
py::array_t<T> ownedArray(Buffer&& values, std::vector<py::ssize_t> shape) {
    auto* owned = new std::decay_t<Buffer>(std::forward<Buffer>(values));
    py::capsule free(owned, [](void* p) { delete static_cast<std::decay_t<Buffer>*>(p); });
    return py::array_t<T>(std::move(shape), owned->data(), free);
}

// An image as a float32 array of shape (height, width, channels): row 0 on
// top, as the library stores it, and no copy.
inline py::array_t<float> imageArray(Image&& image) {
    const std::vector<py::ssize_t> shape{image.height(), image.width(), image.channels()};
    return ownedArray<float>(std::move(image.data()), shape);
}

// An array (height, width) or (height, width, channels), 1 to 4 channels,
// as an image (copied); InputError naming `parameter` otherwise.
using Pixels = py::array_t<float, py::array::c_style | py::array::forcecast>;
Image imageOf(const Pixels& pixels, const std::string& parameter = "pixels");

// The Python keyword of a library parameter: its name in snake case.
std::string keywordOf(const std::string& parameter);

// f() on `threads` worker threads of the library's parallel loops (0: every
// core), in an arena of this call's own: other calls keep theirs.
template <class F>
auto withThreads(int threads, F&& f) {
    if (threads == 0) return f();
    tbb::task_arena arena(threads);
    return arena.execute(std::forward<F>(f));
}

// A table as (title, note, [(key, header, unit, values)]): values a float64
// array where every cell is a number or does not apply (NaN), else a list
// of the cells' text. stochtex/__init__.py makes it a Table (a dict).
py::tuple tableTuple(const Table& table);

// A report (a study's value) as {"title", "sections": [{"heading", "html",
// "tables": [(file, tableTuple)], "figures": [(file, caption, image)],
// "files": {file: text}, "folder"}]} (folder: where the CLI writes the
// section's files, under the report's folder);
// stochtex/studies.py makes it a Report.
py::dict reportDict(Report&& report);

// Sets the numbers an option table describes (OptionMember: the CLI's flags
// and the workbench's widgets come from the same table) from keyword
// arguments named as their parameters in snake case, then checks them all.
// A keyword the table lacks is an InputError naming it.
template <class Options>
void setMembers(Options& options, std::span<const OptionMember<Options>> members, const py::dict& kwargs) {
    for (const auto& [key, value] : kwargs) {
        const std::string keyword = py::str(key);
        const OptionMember<Options>* member = nullptr;
        std::string known;
        for (const OptionMember<Options>& m : members) {
            if (keywordOf(m.info.name) == keyword) member = &m;
            known += (known.empty() ? "" : ", ") + keywordOf(m.info.name);
        }
        if (!member)
            throw InputError::parameter(keyword, "is not an option of this study (its numbers: " + known + ")");
        std::visit(
            [&](auto field) {
                options.*field = value.template cast<std::remove_reference_t<decltype(options.*field)>>();
            },
            member->member);
    }
    checkMembers(options, members);
}

// The numbers an option table describes as keywords → values: what
// setMembers takes back (a value's pickled state).
template <class Options>
py::dict membersDict(const Options& options, std::span<const OptionMember<Options>> members) {
    py::dict out;
    for (const OptionMember<Options>& m : members)
        std::visit([&](auto field) { out[py::str(keywordOf(m.info.name))] = py::cast(options.*field); }, m.member);
    return out;
}

// A texture source Python holds (the zoom texture, a ShaderToy program, a
// pattern's view): use(f) calls f with the library's TextureSource on the
// thread that owns it (a GPU source's GL thread), the GIL released.
class PySource {
public:
    virtual ~PySource() = default;
    virtual void use(const std::function<void(const TextureSource&)>& f) const = 0;
    // What a report calls it.
    virtual std::string name() const = 0;
    // How a study shows its frames: Srgb encodes linear-light colour (a
    // pattern's renders), Linear shows values as they are (display codes, gray).
    virtual Transfer frameTransfer() const { return Transfer::Linear; }
    // A frame study's defaults: the first frame's time and the time between frames.
    virtual double startTime() const { return 0; }
    virtual double frameStep() const { return 1.0 / 30; }
};

// A window of a source: size N or (width, height), origin (x0, y0) its first
// pixel in the source's (default: centred on the source's origin).
using SizeArgument = std::variant<int, std::vector<int>>;
// Its sides, [N] or [width, height]; InputError naming size for another count.
std::vector<int> sizeSides(const SizeArgument& size);
SourceRegion sourceRegion(const SizeArgument& size, const std::optional<std::vector<double>>& origin);

// A Python callable progress(fraction, step) as the library's Progress,
// called from any thread with the GIL taken; it also lets Ctrl-C stop the
// work (a pending signal raises KeyboardInterrupt through the library call).
// The caller must release the GIL while the library runs.
Progress pythonProgress(const py::object& callback);

// The keywords of `kwargs` that `members` names (inTable), or the others:
// for a call whose numbers belong to two option tables.
template <class Options>
py::dict keywordsOf(std::span<const OptionMember<Options>> members, const py::dict& kwargs, bool inTable) {
    py::dict out;
    for (const auto& [key, value] : kwargs) {
        bool named = false;
        for (const OptionMember<Options>& m : members)
            named = named || keywordOf(m.info.name) == py::str(key).cast<std::string>();
        if (named == inTable) out[key] = value;
    }
    return out;
}

void bindImages(py::module_& m);
void bindPatterns(py::module_& m);
void bindSources(py::module_& m);  // first: TextureSource is the others' base
void bindShadertoy(py::module_& m);
void bindStudies(py::module_& m);

}  // namespace stochtex::python
