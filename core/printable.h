#pragma once
// Text from a user's file (a PLY header token, an OBJ line, a JSON key) quoted in a message. Such
// text may hold control characters (a NUL, an escape sequence, a carriage return) that would cut
// the message short, rewrite the terminal or break the one-line promise of eikon::Error, so every
// message that echoes raw input passes it through printable() first.
#include <cstddef>
#include <string>
#include <string_view>

namespace eikon {

// `text` with every control character (below 0x20, and 0x7f) written as an escape: \n, \r, \t,
// and \xNN for the rest; other bytes (UTF-8 included) unchanged. Longer than `maxBytes`, it is
// cut there and "..." appended, so that one corrupt token cannot fill the screen.
std::string printable(std::string_view text, std::size_t maxBytes = 80);

// Whether `text` holds a control character (what printable() would escape).
bool hasControlCharacter(std::string_view text);

}  // namespace eikon
