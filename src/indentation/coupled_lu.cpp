#include "indentation/coupled_lu.hpp"

namespace si {

void CoupledLu::factorize(const SparseMatrix& J, int first, const RowCoupling& coupling) {
  if (lu_ && coupling.members != members_) lu_.reset();
  if (!lu_) {
    lu_ = make_();  // analyses the pattern on its first factorization
    members_ = coupling.members;
  }
  if (coupling.empty()) {
    lu_->factorize(J);
    return;
  }
  coupled_ = coupling.added_to(J, first);
  lu_->factorize(coupled_);
}

}  // namespace si
