// Version of the taut libraries, for `taut --version` and the `tool` attribute of <routes>.
#pragma once

#include <string_view>

namespace taut::router {

std::string_view version();  // e.g. "0.1.0"

}  // namespace taut::router
