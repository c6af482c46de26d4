// The control (check_odr.sh): table_b.cpp with its class named apart, as the fix did.
#include <string>

namespace sg {
struct RunTable {
  std::string path;
  std::string columns;
  double rows = 0.0;
};
}  // namespace sg

int columns_of_a_table();
int main() {
  sg::RunTable t;
  t.rows = 1.0;
  return columns_of_a_table() + static_cast<int>(t.rows) - 4;
}
