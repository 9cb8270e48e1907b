! geom_oracle - ray/primitive intersection in REAL(16), the accuracy ground
! truth for maprt's numeric modes (tests/unit/test_oracle.c).
!
! stdin, one ray per line (free format):
!   kind d0 d1 d2  m11 m12 m13 m14 m21 m22 m23 m24 m31 m32 m33 m34  ox oy oz  dx dy dz
! kind: 0 sphere, 1 cylinder, 2 block, 3 cone, 4 half-space; d0..d2 the
! dimensions as in src/scene/scene.h; m the 3x4 world_from_object matrix; o
! and d the ray in world units (d need not be unit length).
! stdout, one line per ray: "hit t0 t1" (parameters along the unit direction,
! +-1e30 for an unbounded end) or "miss".
program geom_oracle
  use oracle_math
  implicit none
  real(qp), parameter :: big = 1.0e30_qp
  real(qp) :: dim(3), m(3,4), o(3), d(3), a(3,3), inv(3,3), q(3), e(3), w(3)
  real(qp) :: t0, t1, len
  integer :: kind, ios, i
  logical :: hit

  do
    read (*, *, iostat=ios) kind, dim, (m(i, 1), m(i, 2), m(i, 3), m(i, 4), i = 1, 3), o, d
    if (ios /= 0) exit
    a = m(:, 1:3)
    call inverse3(a, inv)
    len = sqrt(sum(d * d))
    d = d / len
    w = o - m(:, 4)
    q = matmul(inv, w)
    e = matmul(inv, d)
    t0 = -big
    t1 = big
    hit = .true.
    select case (kind)
    case (0)
      call quadric(e(1)**2 + e(2)**2 + e(3)**2, q(1)*e(1) + q(2)*e(2) + q(3)*e(3), &
                   q(1)**2 + q(2)**2 + q(3)**2 - dim(1)**2, t0, t1, hit)
    case (1)
      call slab(q(3), e(3), 0.0_qp, dim(2), t0, t1, hit)
      if (hit) call quadric(e(1)**2 + e(2)**2, q(1)*e(1) + q(2)*e(2), &
                            q(1)**2 + q(2)**2 - dim(1)**2, t0, t1, hit)
    case (2)
      do i = 1, 3
        if (hit) call slab(q(i), e(i), 0.0_qp, dim(i), t0, t1, hit)
      end do
    case (3)
      call slab(q(3), e(3), 0.0_qp, dim(3), t0, t1, hit)
      if (hit) call cone(q, e, dim, t0, t1, hit)
    case default
      call slab(q(3), e(3), -big, 0.0_qp, t0, t1, hit)
    end select
    if (hit .and. t0 < t1) then
      write (*, '(a, 2es44.34e3)') 'hit ', t0, t1
    else
      write (*, '(a)') 'miss'
    end if
  end do

contains

  ! Clips [t0,t1] to lo <= p + t v <= hi.
  subroutine slab(p, v, lo, hi, t0, t1, hit)
    real(qp), intent(in) :: p, v, lo, hi
    real(qp), intent(inout) :: t0, t1
    logical, intent(inout) :: hit
    real(qp) :: a, b
    if (v == 0) then
      if (p < lo .or. p > hi) hit = .false.
      return
    end if
    a = (lo - p) / v
    b = (hi - p) / v
    if (a > b) then
      t1 = min(t1, a)
      t0 = max(t0, b)
    else
      t0 = max(t0, a)
      t1 = min(t1, b)
    end if
    if (t0 >= t1) hit = .false.
  end subroutine

  ! Clips [t0,t1] to A t^2 + 2 B t + C <= 0 with A >= 0.
  subroutine quadric(qa, qb, qc, t0, t1, hit)
    real(qp), intent(in) :: qa, qb, qc
    real(qp), intent(inout) :: t0, t1
    logical, intent(inout) :: hit
    real(qp) :: disc, r0, r1
    if (qa == 0) then
      if (qc > 0) hit = .false.
      return
    end if
    disc = qb*qb - qa*qc
    if (disc < 0) then
      hit = .false.
      return
    end if
    r0 = (-qb - sqrt(disc)) / qa
    r1 = (-qb + sqrt(disc)) / qa
    t0 = max(t0, r0)
    t1 = min(t1, r1)
    if (t0 >= t1) hit = .false.
  end subroutine

  ! Cone side: x^2 + y^2 <= (r0 + k z)^2, k = (r1 - r0)/h, within the slab.
  subroutine cone(q, e, dim, t0, t1, hit)
    real(qp), intent(in) :: q(3), e(3), dim(3)
    real(qp), intent(inout) :: t0, t1
    logical, intent(inout) :: hit
    real(qp) :: k, r, rv, qa, qb, qc, disc, x0, x1, a0, a1, b0, b1
    k = (dim(2) - dim(1)) / dim(3)
    r = dim(1) + k*q(3)
    rv = k*e(3)
    qa = e(1)**2 + e(2)**2 - rv*rv
    qb = q(1)*e(1) + q(2)*e(2) - r*rv
    qc = q(1)**2 + q(2)**2 - r*r
    if (qa > 0) then
      call quadric(qa, qb, qc, t0, t1, hit)
      return
    end if
    if (qa == 0) then
      if (qb == 0) then
        if (qc > 0) hit = .false.
      else if (qb > 0) then
        t1 = min(t1, -qc / (2*qb))
      else
        t0 = max(t0, -qc / (2*qb))
      end if
      if (t0 >= t1) hit = .false.
      return
    end if
    disc = qb*qb - qa*qc
    if (disc < 0) return                ! qa < 0: inside everywhere
    x0 = (-qb + sqrt(disc)) / qa        ! qa < 0: x0 <= x1
    x1 = (-qb - sqrt(disc)) / qa
    a0 = t0; a1 = min(t1, x0)
    b0 = max(t0, x1); b1 = t1
    if (a0 < a1) then
      t1 = a1
    else if (b0 < b1) then
      t0 = b0
    else
      hit = .false.
    end if
  end subroutine
end program
