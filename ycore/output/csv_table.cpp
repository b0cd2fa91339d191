#include "ycore/output/csv_table.h"

#include "ycore/output/output_files.h"

namespace ydry {

void CsvTable::append(const std::string& new_rows) {
  rows += new_rows;
  write();
}

void CsvTable::write() const { write_file_atomically(path, header + "\n" + rows); }

}  // namespace ydry
