// The CGAL headers compiled are those of the CGAL that CMake found (CGAL 5.5 in /usr,
// or CGAL 6 unpacked by scripts/fetch_cgal6.sh): a stray include path would mix them.
#include <CGAL/version_macros.h>

#include <cstring>
#include <iostream>

static_assert(CGAL_VERSION_MAJOR == RSR_CMAKE_CGAL_MAJOR && CGAL_VERSION_MINOR == RSR_CMAKE_CGAL_MINOR &&
                  CGAL_VERSION_PATCH == RSR_CMAKE_CGAL_PATCH,
              "CGAL/version.h is not the version that find_package(CGAL) found");

int main()
{
  std::cout << "CGAL " << CGAL_VERSION_STR << " (CGAL_VERSION_NR " << CGAL_VERSION_NR << ")" << std::endl;
  return 0;
}
