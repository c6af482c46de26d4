// The other half (check_odr.sh): the same qualified name, another layout.
#include <string>

namespace sg {
struct Table {
  std::string path;
  std::string columns;
  double rows = 0.0;
};
}  // namespace sg

int columns_of_a_table();
int main() {
  sg::Table t;
  t.rows = 1.0;
  return columns_of_a_table() + static_cast<int>(t.rows) - 4;
}
