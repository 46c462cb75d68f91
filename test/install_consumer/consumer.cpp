// Uses the installed headers: the translation taking a point to the origin must send it there exactly.
#include <CGAL/Poincare_disk_traits_2.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <iostream>
int main()
{
  typedef CGAL::Simple_cartesian<CGAL::Exact_rational> K;
  typedef CGAL::Poincare_disk_traits_2<K> Gt;
  const K::Point_2 a(CGAL::Exact_rational(1, 3), CGAL::Exact_rational(-2, 7));
  const K::Point_2 o = Gt().construct_hyperbolic_translation_2_object()(a)(a);
  const bool ok = o.x() == 0 && o.y() == 0;
  std::cout << (ok ? "1 passed, 0 failed" : "0 passed, 1 failed") << std::endl;
  return ok ? 0 : 1;
}
