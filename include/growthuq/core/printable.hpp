// Input quoted back to the user, made safe for a terminal.
#pragma once

#include <string>
#include <string_view>

namespace growthuq {

// `text` safe to print on a terminal as one line: every control character (C0 including NUL,
// newline and ESC; DEL; the C1 controls U+0080 to U+009F as UTF-8) is written as \xNN, so a NUL
// or an escape sequence in a file name, a value or a line name shows as what it is instead of
// acting on the terminal. Printable text, UTF-8 included, is unchanged, and so is text already
// made printable (a backslash is not escaped).
//
// The one helper for every message that quotes input: InputError stores its location and
// problem through it (so every error message is one line), and the warnings and the last-resort
// messages of main() go through it.
std::string printable(std::string_view text);

}  // namespace growthuq
