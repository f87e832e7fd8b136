// quoted.h - untrusted text (a token, a header line, a name from a file) shown in a one-line
// error message.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace shpack::io {

// Appends `ch`, a control character (C0 or DEL) written as \xNN, so that text from a file or
// the command line cannot move the cursor, colour the terminal or break the line.
void append_printable(std::string& line, char ch);

// `text` in single quotes for a message: at most `shown` bytes of it, "..." inside the quotes
// when cut (a hostile token may be megabytes long), control characters as \xNN.
std::string quoted(std::string_view text, std::size_t shown = 64);

}  // namespace shpack::io
