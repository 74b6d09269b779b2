#include "stochtex/pattern/response.h"

#include <stdexcept>

namespace stochtex {

std::unique_ptr<Response> makeResponse(const ResponseOptions& options, const ColormapTable& h) {
    switch (options.kind) {
        case ResponseKind::PrefilteredColormap:
            return std::make_unique<PrefilteredColormapResponse>(h, options.prefilter);
    }
    throw std::invalid_argument("makeResponse: unknown response kind " + std::to_string(int(options.kind)));
}

}  // namespace stochtex
