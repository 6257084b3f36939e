// The text boxes of a PDF as poppler sees them (`pdftotext -bbox`, from
// poppler-utils): the page size and each word's box in points (origin top
// left, y down), for the figure tests.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"

namespace rollspin::test {

struct PdfWord {
  double x0, y0, x1, y1;
  std::string text;
};

struct PdfPage {
  double width = 0.0, height = 0.0;
  std::vector<PdfWord> words;
};

// pdftotext -bbox writes XHTML: <page width=".." height=".."> and one
// <word xMin=".." yMin=".." xMax=".." yMax="..">text</word> per word.
inline PdfPage readPdfWords(const std::filesystem::path& pdf) {
  const std::filesystem::path html = pdf.string() + ".html";
  const std::string command = "pdftotext -bbox '" + pdf.string() + "' '" + html.string() + "'";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  const std::string text = readFile(html);
  PdfPage page;
  std::smatch m;
  if (std::regex_search(text, m, std::regex(R"re(<page width="([0-9.]+)" height="([0-9.]+)")re"))) {
    page.width = std::stod(m[1]);
    page.height = std::stod(m[2]);
  }
  const std::regex word(
      R"re(<word xMin="([0-9.\-]+)" yMin="([0-9.\-]+)" xMax="([0-9.\-]+)" yMax="([0-9.\-]+)">([^<]*)</word>)re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator(); ++it)
    page.words.push_back(
        {std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4]), (*it)[5]});
  return page;
}

// Words of different lines overlap when their boxes share more than a
// sliver (the font's boxes include the ascent and descent: lines a line
// step apart touch at most).
inline bool wordsOverlap(const PdfWord& a, const PdfWord& b) {
  const double w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0), h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return w > 0.3 && h > 0.25 * std::min(a.y1 - a.y0, b.y1 - b.y0);
}

}  // namespace rollspin::test
