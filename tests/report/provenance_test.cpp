// Every page's stamp (report/detail/provenance.hpp): the command line as a shell reads it back, the scene hash as
// the published FNV-1a 64 of the text (an implementation here, from its definition), the date in UTC.
#include "rbcstab/report/detail/provenance.hpp"

#include <gtest/gtest.h>

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <string>

namespace rbcstab::detail {
namespace {

// FNV-1a 64 from its definition (offset basis 14695981039346656037, prime 1099511628211).
std::string fnv1a_64(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (unsigned char c : text) h = (h ^ c) * 0x100000001b3ull;
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}

// What /bin/sh prints for printf %s WORD: the word as the shell reads it.
std::string as_the_shell_reads(const std::string& word) {
  FILE* p = popen(("printf %s " + word).c_str(), "r");
  std::string out;
  for (int c; p && (c = std::fgetc(p)) != EOF;) out += static_cast<char>(c);
  if (p) pclose(p);
  return out;
}

TEST(Provenance, QuotedWordsReadBackAsTheyWere) {
  for (const std::string w : {"plain", "--scene", "a b", "it's", "$HOME", "x;y", "\"q\"", "*", "tab\there", "back\\"})
    EXPECT_EQ(as_the_shell_reads(shell_quoted(w)), w) << shell_quoted(w);
  EXPECT_EQ(shell_quoted("--output=dir/x.toml"), "--output=dir/x.toml");  // nothing to quote: left as it is
  EXPECT_EQ(as_the_shell_reads("a b"), "ab");  // the oracle itself: an unquoted space splits the word
}

TEST(Provenance, StampsTheCommandTheSceneHashAndTheDate) {
  const Provenance p = make_provenance({"name = 'x'\n"}, "scene.toml");
  EXPECT_EQ(p.scene_hash, fnv1a_64("name = 'x'\n") + " (scene.toml)");
  EXPECT_EQ(fnv1a_64(""), "cbf29ce484222325");                                // the definition's empty-string value
  EXPECT_NE(p.command.find("report_tests"), std::string::npos) << p.command;  // this process
  const std::string shape = "dddd-dd-ddTdd:dd:ddZ";  // ISO 8601 in UTC: d a digit, the rest as written
  ASSERT_EQ(p.date.size(), shape.size()) << p.date;
  for (std::size_t k = 0; k < shape.size(); ++k)
    EXPECT_TRUE(shape[k] == 'd' ? std::isdigit(static_cast<unsigned char>(p.date[k])) != 0 : p.date[k] == shape[k])
        << p.date;
  EXPECT_FALSE(p.version.empty());
  EXPECT_FALSE(p.revision.empty());
  // Several scenes: joined by a blank line, so that ("a", "b") and ("a\n\nb") are the same text and ("ab") not.
  EXPECT_EQ(make_provenance({"a", "b"}, "two").scene_hash, fnv1a_64("a\n\nb") + " (two)");
  EXPECT_NE(make_provenance({"a", "b"}, "two").scene_hash, make_provenance({"ab"}, "two").scene_hash);
  const Provenance back = provenance_from_json(provenance_json(p));
  EXPECT_EQ(provenance_html(back), provenance_html(p));
  EXPECT_NE(provenance_html(p).find("<code>"), std::string::npos);
}

}  // namespace
}  // namespace rbcstab::detail
