// Minimal test harness shared by the package test executables.
//
//   CGAL_HC_CHECK(cond)            records a failure (file, line, expression) and goes on
//   CGAL_HC_CHECK_MSG(cond, msg)   same, with a message streamed after the expression
//   CGAL_HC_CHECK_THROWS(expr, E)  expr must throw an exception of type E
//   CGAL_HC_TEST_CASE(name)        defines and registers a test case
//   return cgal_hc_test::run_all(argc, argv);   runs all cases (or those whose name contains argv[1]),
//                                               prints "N passed, M failed" and returns non-zero on failure.
#ifndef CGAL_HC_TEST_H
#define CGAL_HC_TEST_H

#include <chrono>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace cgal_hc_test {

struct Case { std::string name; std::function<void()> body; };

inline std::vector<Case>& registry() { static std::vector<Case> r; return r; }
inline long& failures_in_case() { static long n = 0; return n; }
inline long& checks_in_case() { static long n = 0; return n; }

struct Registrar {
  Registrar(const char* name, std::function<void()> body) { registry().push_back({name, std::move(body)}); }
};

inline void report_failure(const char* file, int line, const std::string& what) {
  ++failures_in_case();
  if(failures_in_case() <= 20)
    std::cerr << "  FAILED " << file << ":" << line << ": " << what << std::endl;
}

inline int run_all(int argc, char** argv) {
  const std::string filter = argc > 1 ? argv[1] : "";
  long passed = 0, failed = 0;
  for(const Case& c : registry()) {
    if(!filter.empty() && c.name.find(filter) == std::string::npos) continue;
    failures_in_case() = 0; checks_in_case() = 0;
    auto t0 = std::chrono::steady_clock::now();
    try { c.body(); }
    catch(const std::exception& e) { report_failure(c.name.c_str(), 0, std::string("uncaught exception: ") + e.what()); }
    catch(...) { report_failure(c.name.c_str(), 0, "uncaught unknown exception"); }
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const bool ok = failures_in_case() == 0 && checks_in_case() > 0;
    if(checks_in_case() == 0) std::cerr << "  FAILED " << c.name << ": the case made no check" << std::endl;
    std::cout << (ok ? "[ ok ] " : "[FAIL] ") << c.name << "  (" << checks_in_case() << " checks, "
              << failures_in_case() << " failed, " << s << " s)" << std::endl;
    (ok ? passed : failed)++;
  }
  std::cout << passed << " passed, " << failed << " failed" << std::endl;
  return failed == 0 && passed > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

} // namespace cgal_hc_test

#define CGAL_HC_CONCAT_(a, b) a##b
#define CGAL_HC_CONCAT(a, b) CGAL_HC_CONCAT_(a, b)
#define CGAL_HC_TEST_CASE(name)                                                          \
  static void CGAL_HC_CONCAT(cgal_hc_case_, name)();                                     \
  static cgal_hc_test::Registrar CGAL_HC_CONCAT(cgal_hc_reg_, name)(#name, &CGAL_HC_CONCAT(cgal_hc_case_, name)); \
  static void CGAL_HC_CONCAT(cgal_hc_case_, name)()

#define CGAL_HC_CHECK_MSG(cond, msg)                                                     \
  do { ++cgal_hc_test::checks_in_case();                                                 \
       if(!(cond)) { std::ostringstream cgal_hc_os_; cgal_hc_os_ << #cond << "  " << msg; \
                     cgal_hc_test::report_failure(__FILE__, __LINE__, cgal_hc_os_.str()); } } while(0)
#define CGAL_HC_CHECK(cond) CGAL_HC_CHECK_MSG(cond, "")
#define CGAL_HC_CHECK_THROWS(expr, E)                                                    \
  do { ++cgal_hc_test::checks_in_case(); bool cgal_hc_thrown_ = false;                   \
       try { (void)(expr); } catch(const E&) { cgal_hc_thrown_ = true; } catch(...) {}   \
       if(!cgal_hc_thrown_) cgal_hc_test::report_failure(__FILE__, __LINE__, "expected " #E " from " #expr); } while(0)

#endif // CGAL_HC_TEST_H
