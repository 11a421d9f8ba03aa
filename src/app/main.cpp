#include <iostream>
int main() {
  std::cout << "shellindent\n";
}
