#include "oracle/algebraic/filter_context.hpp"

namespace anisocert::oracle {
namespace {

thread_local FilterContext fallback;
thread_local FilterContext* installed = nullptr;

}  // namespace

FilterContext& filter_context() { return installed ? *installed : fallback; }

FilterScope::FilterScope(FilterContext& c) : previous_(installed) { installed = &c; }
FilterScope::~FilterScope() { installed = previous_; }

}  // namespace anisocert::oracle
