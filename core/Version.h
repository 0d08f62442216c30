#pragma once
// Program version (from CMake's project version).
namespace hsmu {
const char* versionString();
}
