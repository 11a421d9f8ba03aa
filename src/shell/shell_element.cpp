#include "shell/shell_element.hpp"

#include "core/error.hpp"
#include "shell/quad4_shell.hpp"

namespace si {

std::unique_ptr<ShellElement> make_shell_element(ElementType type) {
  switch (type) {
    case ElementType::kMitc4:
      return std::make_unique<Quad4Shell>(mitc4_options());
    case ElementType::kMitc4Plain:
      return std::make_unique<Quad4Shell>(mitc4_plain_options());
    case ElementType::kBernstein4:
      return std::make_unique<Quad4Shell>(bernstein4_options());
  }
  throw Error(ErrorKind::kInternal, "make_shell_element: unknown element type");
}

}  // namespace si
