#pragma once
// Names of POV-Ray's string built-ins (POV-Ray 3.7 reference, "String Functions"), so that the
// expression parser can tell a string expression or a string query from a number before reading it.
#include <string>

namespace snell::sdl {

/// Functions whose value is a string: concat, str, vstr, chr, substr, strupr, strlwr, datetime.
bool is_string_function(const std::string& name);
/// Functions of strings whose value is a number: strlen, strcmp, val, asc, file_exists.
bool is_numeric_string_function(const std::string& name);


}  // namespace snell::sdl
