// The public header compiles alone as C++ (-pedantic -Werror), declares
// C linkage, and its structs are standard-layout with struct_size first.
#include <halfslip/halfslip.h>
#include <halfslip/halfslip.h>  // include guard

#include <cstddef>

#if __cplusplus >= 201103L
#  include <type_traits>
static_assert(std::is_standard_layout<hs_scene>::value && std::is_trivial<hs_scene>::value, "hs_scene is POD");
static_assert(std::is_standard_layout<hs_summary>::value && std::is_trivial<hs_summary>::value, "hs_summary");
static_assert(std::is_standard_layout<hs_ref_scene>::value, "hs_ref_scene");
static_assert(std::is_standard_layout<hs_geometry>::value && std::is_trivial<hs_geometry>::value, "hs_geometry");
static_assert(offsetof(hs_scene, struct_size) == 0 && offsetof(hs_options, struct_size) == 0 &&
                  offsetof(hs_summary, struct_size) == 0 && offsetof(hs_ref_scene, struct_size) == 0 &&
                  offsetof(hs_geometry, struct_size) == 0 && offsetof(hs_ref_summary, struct_size) == 0,
              "struct_size comes first");
static_assert(std::is_same<decltype(&hs_solve), int (*)(const hs_scene *, const hs_options *, hs_solution **)>::value,
              "hs_solve signature");
#endif

// The functions are declared with C language linkage: their addresses convert
// to pointers to an extern "C" function type.
extern "C" typedef int hs_solve_fn(const hs_scene *, const hs_options *, hs_solution **);
int hs_header_check_cxx();
int hs_header_check_cxx() {
  hs_solve_fn *f = hs_solve;
  return f == 0 ? 1 : 0;
}
