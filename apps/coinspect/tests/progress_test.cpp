#include "progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

namespace coinspect::app {
namespace {

// Everything written to a temporary file, read back.
std::string contentOf(std::FILE* file) {
  std::fflush(file);
  std::rewind(file);
  std::string text;
  char buffer[4096];
  size_t count = 0;
  while ((count = std::fread(buffer, 1, sizeof buffer, file)) > 0)
    text.append(buffer, count);
  return text;
}

size_t countOf(const std::string& text, char c) {
  return static_cast<size_t>(std::count(text.begin(), text.end(), c));
}

TEST(ProgressLine, AFileIsNotATerminal) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  EXPECT_FALSE(ProgressLine(file, "run", 10.0).terminal());
  std::fclose(file);
}

TEST(ProgressLine, PlainOutputHasOneLinePerTenPercent) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  {
    ProgressLine progress(file, "progress", 20.0, ProgressLine::Style::Plain);
    for (int second = 1; second <= 21; ++second)  // one more than the total: no 11th line
      progress.update(second, 0.5 * second, 5u * static_cast<size_t>(second), 150);
    progress.finish();
  }
  const std::string text = contentOf(file);
  std::fclose(file);
  EXPECT_EQ(countOf(text, '\n'), 10u) << text;
  EXPECT_EQ(countOf(text, '\r'), 0u);
  EXPECT_NE(text.find("progress   t 2.0 / 20.0 s ( 10 %), Q = 1.00, detected 10 / 150"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("t 20.0 / 20.0 s (100 %)"), std::string::npos) << text;
}

TEST(ProgressLine, PlainOutputOfARunThatEndedEarlyEndsWithItsLastState) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  ProgressLine progress(file, "run", 20.0, ProgressLine::Style::Plain);
  for (int step = 1; step <= 15; ++step)  // 0.5 s steps up to 7.5 s: lines at 2, 4 and 6 s
    progress.update(0.5 * step, 1.0, 3, 150);
  progress.finish();
  progress.finish();  // once only
  const std::string text = contentOf(file);
  std::fclose(file);
  EXPECT_EQ(countOf(text, '\n'), 4u) << text;
  EXPECT_NE(text.find("t 7.5 / 20.0 s ( 38 %)"), std::string::npos) << text;
}

TEST(ProgressLine, TerminalOutputRedrawsOneLineInPlace) {
  std::FILE* file = std::tmpfile();
  ASSERT_NE(file, nullptr);
  ProgressLine progress(file, "run", 100.0, ProgressLine::Style::Terminal);
  EXPECT_TRUE(progress.terminal());
  const auto start = std::chrono::steady_clock::now();
  for (int step = 1; step <= 1000; ++step)
    progress.update(0.1 * step, 2.0, 7, 150);
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string during = contentOf(file);
  EXPECT_EQ(countOf(during, '\n'), 0u);
  // The first update draws; later ones at most 10 per wall second.
  EXPECT_GE(countOf(during, '\r'), 1u);
  EXPECT_LE(static_cast<double>(countOf(during, '\r')), 1.0 + 10.0 * wall + 1.0);
  progress.finish();
  const std::string text = contentOf(file);
  std::fclose(file);
  EXPECT_EQ(countOf(text, '\n'), 1u);
  EXPECT_EQ(text.back(), '\n');
  // The final redraw shows the last state.
  const std::string last = text.substr(text.rfind('\r'));
  EXPECT_NE(last.find("t 100.0 / 100.0 s (100 %), Q = 2.00, detected 7 / 150"), std::string::npos)
      << last;
}

}  // namespace
}  // namespace coinspect::app
