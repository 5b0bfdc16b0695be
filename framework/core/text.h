// Bounding user text before it reaches a message (issue 21 item 4): a
// 10,000-character tag name echoed into an error is noise, not help.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace cooperage {

/// The longest piece of user text an error message echoes, in characters.
inline constexpr std::size_t kEchoLimit = 80;

/// `text` as one printable line of at most `limit` characters: control
/// characters (newlines, tabs, escapes) become '?', and a longer text is cut
/// to its first limit - 1 characters followed by "…". Multi-byte UTF-8
/// sequences are kept whole (counted as one character) or cut before.
std::string clip(std::string_view text, std::size_t limit = kEchoLimit);

/// A number for a message: six significant digits, no trailing zeros
/// ("0.5", "3.1095", "1e+06").
std::string number_text(double value);

/// A point for a message: "(1.25, -3, 40.12)", four significant digits
/// each (enough to find the spot on a part, short enough for a line).
std::string point_text(double x, double y, double z);

/// A file path for a message: like clip(), but a long path keeps its end
/// (the file name) and loses its beginning: "…/deep/dir/part.step".
std::string clip_path(std::string_view path, std::size_t limit = kEchoLimit);

/// A file's extension in lower case, with its dot (".step" for
/// "Part.STEP"); "" without one. File kinds are told apart by it.
std::string lower_extension(const std::string& path);

}  // namespace cooperage
