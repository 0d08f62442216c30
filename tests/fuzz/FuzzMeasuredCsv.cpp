// libFuzzer target for the measured-data CSV importer (core/offline/MeasuredDataCsv): any
// text read from a stream gives a history with finite values or a MeasuredDataError; the
// --units and --columns option parsers likewise.
#include "core/offline/MeasuredDataCsv.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

using namespace hsmu;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        std::istringstream in(text);
        (void)readMeasuredDataCsv(in, "fuzz.csv");
    } catch (const MeasuredDataError&) {
    }
    const std::string first = text.substr(0, text.find('\n'));
    try {
        (void)parseMeasuredDataUnits(first);
    } catch (const MeasuredDataError&) {
    }
    try {
        (void)parseMeasuredDataColumns(first);
    } catch (const MeasuredDataError&) {
    }
    return 0;
}
