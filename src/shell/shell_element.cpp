#include "shell/shell_element.hpp"

#include "core/error.hpp"
#include "shell/quad4_shell.hpp"

namespace si {

std::unique_ptr<ShellElement> make_shell_element(const std::string& name) {
  if (name == "mitc4") return std::make_unique<Quad4Shell>(mitc4_options());
  if (name == "mitc4-plain") return std::make_unique<Quad4Shell>(mitc4_plain_options());
  if (name == "bernstein4") return std::make_unique<Quad4Shell>(bernstein4_options());
  throw_input("unknown shell element '" + name + "' (known: mitc4, mitc4-plain, bernstein4)");
}

}  // namespace si
