// Escaping of text from files and the relative links of the page.
#include "html.h"

#include <gtest/gtest.h>

namespace limber::report {
namespace {

TEST(HtmlEscape, EscapesMarkupAndQuotes) {
  EXPECT_EQ(markup_escape("<script>alert(\"x\") & 'y'</script>"),
            "&lt;script&gt;alert(&quot;x&quot;) &amp; &#39;y&#39;&lt;/script&gt;");
  EXPECT_EQ(markup_escape("plain R3 joint"), "plain R3 joint");
}

TEST(RelativeUrl, PercentEncodesAndWalksUp) {
  EXPECT_EQ(relative_url("/tmp/run a/report", "/tmp/run a/animation.mp4"), "../animation.mp4");
  EXPECT_EQ(relative_url("/tmp/out", "/tmp/run a/animation.mp4"), "../run%20a/animation.mp4");
  EXPECT_EQ(relative_url("/tmp/out", "/tmp/out/x\"<.png"), "x%22%3C.png");
}

// Safe characters only, and distinct texts give distinct stems (render/file_stem.h).
TEST(FileStem, KeepsOnlySafeCharacters) {
  EXPECT_EQ(file_stem("R3"), "R3");
  EXPECT_EQ(file_stem("../a b<c>"), "~2E~2E~2Fa~20b~3Cc~3E");
  EXPECT_EQ(file_stem(""), "~");
  EXPECT_NE(file_stem("a b"), file_stem("a_b"));
}

TEST(ReadableStem, KeepsSafeCharactersAndBlanksTheRest) {
  EXPECT_EQ(readable_stem("R3 force z [N]"), "R3_force_z__N_");
  EXPECT_EQ(readable_stem("../a b<c>"), "___a_b_c_");
  EXPECT_EQ(readable_stem(""), "_");
}

}  // namespace
}  // namespace limber::report
