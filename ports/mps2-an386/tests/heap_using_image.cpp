// An image that allocates from the heap, built only by a test: firmware has no heap, so it must not link.

#include <cstdlib>

#include "duet/mps2_an386/board.hpp"

namespace {
// The allocation escapes through a volatile pointer, so that the compiler cannot elide it.
int* volatile allocated = nullptr;
}  // namespace

int main() {
  duet::mps2_an386::initialize();
#if defined(USE_OPERATOR_NEW)
  allocated = new int(42);
#else
  allocated = static_cast<int*>(std::malloc(sizeof(int)));
#endif
  return allocated == nullptr ? 1 : 0;
}
