// Reading named columns of a CSV file with a header row (history.csv) back as numbers.
#pragma once

#include <string>
#include <vector>

namespace vulnus::io
{
/// The values of each of `names`, in file order, one vector per name. Throws
/// std::runtime_error naming the file and line when the file cannot be read, a name is not
/// in its header or a field is not a number.
std::vector<std::vector<double>> read_csv_columns(const std::string& path,
                                                  const std::vector<std::string>& names);
} // namespace vulnus::io
