#pragma once
// Finds and opens snell's plugins (shared modules built beside the program: libsnell_oiio.so,
// libsnell_assimp.so). Libraries with long dependency chains live in plugins so that a render which does
// not need them does not pay for loading them at start-up.
#include <string>

namespace snell::io {

/// dlopen's handle of the plugin `file_name`, looked up beside the running program first, then in the build
/// folder snell was compiled in (test programs live one folder below it); null with `error` set when none
/// loads. Handles stay open for the life of the process.
void* open_plugin(const char* file_name, std::string& error);

/// The symbol `name` of an open plugin, or null.
void* plugin_symbol(void* handle, const char* name);

}  // namespace snell::io
