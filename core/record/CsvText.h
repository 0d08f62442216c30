#pragma once
// CsvText: how our CSV exports write a field: numbers in the shortest form that reads back
// to the same double (std::to_chars: '.' decimal point whatever the locale; NaN as "nan"),
// text quoted (RFC 4180) when it holds a comma, a quote or a line break.

#include <string>
#include <vector>

namespace hsmu::csvtext {

std::string number(double x);
std::string quoted(const std::string& text);
/// "name [unit]" (just the name when unit is empty), quoted as needed.
std::string column(const std::string& name, const std::string& unit);
/// Fields joined by commas, without a line end.
std::string join(const std::vector<std::string>& fields);

} // namespace hsmu::csvtext
