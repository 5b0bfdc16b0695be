// clip / clip_path (framework/core/text.h): user text in messages is one
// bounded line (issue 21 item 4).
#include "framework/core/text.h"

#include <gtest/gtest.h>

#include <string>

namespace cooperage {
namespace {

const std::string kEllipsis = "\xE2\x80\xA6";

// Characters, counting a UTF-8 sequence as one.
std::size_t characters(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

TEST(Clip, ShortTextIsKept) {
  EXPECT_EQ(clip("brick"), "brick");
  EXPECT_EQ(clip(""), "");
  EXPECT_EQ(clip(std::string(80, 'a')), std::string(80, 'a'));
}

TEST(Clip, LongTextIsCutTo80CharactersWithAnEllipsis) {
  const std::string cut = clip(std::string(10000, 'n'));
  EXPECT_EQ(characters(cut), 80u);
  EXPECT_EQ(cut, std::string(79, 'n') + kEllipsis);
  EXPECT_EQ(clip(std::string(81, 'x')), std::string(79, 'x') + kEllipsis);
  EXPECT_EQ(clip("abcdef", 4), "abc" + kEllipsis);
}

TEST(Clip, ControlCharactersBecomeQuestionMarksSoTheMessageStaysOneLine) {
  EXPECT_EQ(clip("a\nb\tc\x1b[31m"), "a?b?c?[31m");
  EXPECT_EQ(clip(std::string("a\0b", 3)), "a?b");
}

TEST(Clip, Utf8SequencesAreNeverSplit) {
  const std::string e = "\xC3\xA9";  // é
  std::string text;
  for (int i = 0; i < 100; ++i) text += e;
  const std::string cut = clip(text);
  EXPECT_EQ(characters(cut), 80u);
  EXPECT_EQ(cut.substr(0, 2 * 79), text.substr(0, 2 * 79));
  // A stray continuation byte or a truncated sequence is not text: '?'.
  EXPECT_EQ(clip("\x80"
                 "a\xC3"),
            "?a?");
}

TEST(ClipPath, KeepsTheFileNameOfALongPath) {
  const std::string path = "/" + std::string(300, 'd') + "/part.step";
  const std::string cut = clip_path(path);
  EXPECT_EQ(characters(cut), 80u);
  EXPECT_EQ(cut.substr(0, kEllipsis.size()), kEllipsis);
  EXPECT_EQ(cut.substr(cut.size() - 10), "/part.step");
  EXPECT_EQ(clip_path("examples/brick.xml"), "examples/brick.xml");
}

TEST(LowerExtension, KindsOfFilesAreToldApartWhateverTheirCase) {
  EXPECT_EQ(lower_extension("Part.STEP"), ".step");
  EXPECT_EQ(lower_extension("/a/b.v2/job.Xml"), ".xml");
  EXPECT_EQ(lower_extension("/a/b.v2/README"), "");
  EXPECT_EQ(lower_extension("mesh.tar.GZ"), ".gz");
}

}  // namespace
}  // namespace cooperage
