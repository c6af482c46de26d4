// One half of a deliberate one-definition-rule violation (check_odr.sh): a class sg::Table
// here, a different sg::Table in table_b.cpp, as scenario/ and analysis/ once had two
// sg::CsvTable. Not part of softgrain.
#include <string>
#include <vector>

namespace sg {
class Table {
 public:
  explicit Table(int columns);
  ~Table();
  std::vector<std::string> cells;
  int columns;
};
Table::Table(int n) : columns(n) {}
Table::~Table() = default;
}  // namespace sg

int columns_of_a_table() {
  return sg::Table(3).columns;
}
