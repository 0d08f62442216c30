#include "core/Version.h"

namespace hsmu {
const char* versionString() { return HSMU_VERSION; }
} // namespace hsmu
