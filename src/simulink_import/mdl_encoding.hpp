#pragma once
// A classic .mdl file's bytes are in the encoding its `SavedCharacterEncoding` names; the reader works on UTF-8.

#include <string>
#include <string_view>

#include "duet/support/result.hpp"

namespace duet::simulink_import {

// The file's text as UTF-8, line for line as in the file. ISO-8859-1, windows-1252 and UTF-8 (or no encoding named:
// then UTF-8, which ASCII is) are read; any other encoding is refused, since a multi-byte encoding such as Shift_JIS
// can hide a backslash or a quote in a character's second byte and no scan of quotes would be safe.
Result<std::string> mdl_text_as_utf8(std::string_view bytes, const std::string& file);

}  // namespace duet::simulink_import
