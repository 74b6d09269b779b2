#include "stochtex/workbench/options.h"

#include <algorithm>

#include "stochtex/core/error.h"
#include "stochtex/pattern/param_info.h"
#include "stochtex/pattern/view.h"

namespace stochtex {

std::span<const OptionMember<WorkbenchOptions>> workbenchOptionsMembers() {
    using O = WorkbenchOptions;
    static const OptionMember<O> members[] = {
        {"frames", "Quit after this many frames (0: when the window closes)", 0, 1e6, &O::frames},
    };
    return members;
}

void validateWorkbenchOptions(const WorkbenchOptions& o) {
    const View& v = o.camera.view;
    if (std::min(v.width, v.height) < 16 || std::max(v.width, v.height) > 8192)
        throw InputError::parameter(
            "size", "must be in [16, 8192] per side, got " + std::to_string(v.width) + "x" + std::to_string(v.height));
    if (o.filter.source != StatisticsSource::Point && o.filter.source != StatisticsSource::Estimators)
        throw InputError::parameter("filter", "the window draws none, paper or smooth, got " + filterName(o.filter));
    checkInteger(anisoParam(), o.filter.aniso);
    checkNumber(cameraTiltParam(), o.camera.tiltDeg, " degrees");
    checkNumber(viewScaleParam(), o.camera.view.scale);
    checkMembers(o, workbenchOptionsMembers());
    if (o.view == WorkbenchView::Mesh && !o.mesh) throw InputError::parameter("view", "mesh needs a mesh file");
    if (!o.screenshot.empty() && o.frames == 0)
        throw InputError::parameter("frames", "must be given with a screenshot (it is of the last frame)");
    validateShadertoySettings(o.shadertoy);
}

}  // namespace stochtex
