#include "stochtex/pattern/response.h"

#include <stdexcept>

#include "stochtex/core/error.h"

namespace stochtex {

std::unique_ptr<Response> makeResponse(const ResponseOptions& options, const ColormapTable& h) {
    switch (options.kind) {
        case ResponseKind::PrefilteredColormap:
            return std::make_unique<PrefilteredColormapResponse>(h, options.prefilter);
        case ResponseKind::Lean:
            throw InputError::parameter("response", "lean shades a file's normal map, which its program "
                                                    "(GraphPattern::build) carries, not a colormap");
    }
    throw std::invalid_argument("makeResponse: unknown response kind " + std::to_string(int(options.kind)));
}

}  // namespace stochtex
