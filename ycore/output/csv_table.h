// A CSV file that grows a row at a time: after each append the whole file is written again,
// atomically, so it is never half-written, and its rows are kept for checkpoints.
#pragma once

#include <string>

namespace ydry {

struct CsvTable {
  std::string path;
  std::string header;  // the first line, without its newline
  std::string rows;    // every row so far, each ending in a newline

  // Adds `new_rows` (whole lines) and writes the file.
  void append(const std::string& new_rows);
  // Writes the file: the header, then the rows.
  void write() const;
};

}  // namespace ydry
