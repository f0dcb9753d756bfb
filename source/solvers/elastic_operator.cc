#include <lithostress/solvers/elastic_operator.templates.h>

namespace lithostress
{
#define LITHOSTRESS_INSTANTIATE(DEGREE)             \
  template class ElasticOperator<2, DEGREE, float>; \
  template class ElasticOperator<2, DEGREE, double>;
  LITHOSTRESS_INSTANTIATE(1)
  LITHOSTRESS_INSTANTIATE(2)
  LITHOSTRESS_INSTANTIATE(3)
#undef LITHOSTRESS_INSTANTIATE
} // namespace lithostress
