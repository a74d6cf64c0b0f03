#include "router/version.h"

namespace taut::router {

std::string_view version() { return TAUT_VERSION_STRING; }

}  // namespace taut::router
