! oracle_math - what the REAL(16) oracles share: the working precision and
! the inverse of a 3x3 matrix by cofactors.
module oracle_math
  implicit none
  integer, parameter :: qp = selected_real_kind(30)
contains
  subroutine inverse3(a, v)
    real(qp), intent(in) :: a(3,3)
    real(qp), intent(out) :: v(3,3)
    real(qp) :: det
    v(1,1) = a(2,2)*a(3,3) - a(2,3)*a(3,2)
    v(1,2) = a(1,3)*a(3,2) - a(1,2)*a(3,3)
    v(1,3) = a(1,2)*a(2,3) - a(1,3)*a(2,2)
    v(2,1) = a(2,3)*a(3,1) - a(2,1)*a(3,3)
    v(2,2) = a(1,1)*a(3,3) - a(1,3)*a(3,1)
    v(2,3) = a(1,3)*a(2,1) - a(1,1)*a(2,3)
    v(3,1) = a(2,1)*a(3,2) - a(2,2)*a(3,1)
    v(3,2) = a(1,2)*a(3,1) - a(1,1)*a(3,2)
    v(3,3) = a(1,1)*a(2,2) - a(1,2)*a(2,1)
    det = a(1,1)*v(1,1) + a(1,2)*v(2,1) + a(1,3)*v(3,1)
    v = v / det
  end subroutine
end module
