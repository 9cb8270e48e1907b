! ids_oracle - the primary rays of a scene traced in REAL(16): camera, every
! primitive and face, CSG span lists, separate objects, (u,v). The ground
! truth for `maprt render --ids` (docs/idmap.md). Written from the scene
! model and docs/primitives.md alone; it shares no code with the tracer.
!
! usage: ids_oracle IN OUT
! IN (free format, written by idmap_oracle_input in src/render/idmap.c):
!   W H S
!   eye(3) look(3) up(3) fov_deg
!   nprims nnodes nroots
!   nprims lines: kind d0 d1 d2 m11 m12 m13 m14 m21 ... m34
!   nnodes lines: op left right prim     (op 0 leaf, 1 union, 2 inter, 3 diff)
!   nroots lines: node
! S is the scene's size (half-width of the box of its bounded primitives).
! OUT: a stream of W*H records, top row first, each int32 prim, int32
! face, int32 flags (1: ambiguous), real64 t, real64 u, real64 v.
! Boundaries closer than 1e-9 S are one boundary (coincident faces given by
! different transforms); a pixel whose hit has another span end or face
! crossing within the error window, that passes a primitive within the
! window of tangency before its hit, or that meets its face within 3
! degrees of grazing, is flagged.
program ids_oracle
  use oracle_math
  implicit none
  integer, parameter :: dp = kind(1.0d0)
  integer, parameter :: maxs = 256
  real(qp), parameter :: big = 1.0e30_qp
  integer :: w, h, np, nn, nr, i, j, x, y
  real(qp) :: s, eye(3), look(3), up(3), fov, fwd(3), rt(3), uu(3), th, asp, sx, sy, d(3)
  real(qp), allocatable :: dims(:,:), mat(:,:,:), inv(:,:,:)
  integer, allocatable :: pkind(:), nop(:), nl(:), nr_(:), npr(:), roots(:)
  real(qp) :: tmerge, ends(4 * maxs), grazes(maxs)
  integer :: nends, ngraze, nc, nc0
  real(qp) :: grr
  character(len=4096) :: inpath, outpath
  ! current hit
  real(qp) :: bt
  integer :: bp, bf, be

  call get_command_argument(1, inpath)
  call get_command_argument(2, outpath)
  open (unit=10, file=trim(inpath), status='old', action='read')
  open (unit=11, file=trim(outpath), access='stream', form='unformatted', status='replace', action='write')
  read (10, *) w, h, s
  read (10, *) eye, look, up, fov
  read (10, *) np, nn, nr
  allocate (dims(3, np), mat(3, 4, np), inv(3, 3, np), pkind(np))
  allocate (nop(nn), nl(nn), nr_(nn), npr(nn), roots(nr))
  do i = 1, np
    read (10, *) pkind(i), dims(:, i), (mat(j, 1, i), mat(j, 2, i), mat(j, 3, i), mat(j, 4, i), j = 1, 3)
    call inverse3(mat(:, 1:3, i), inv(:, :, i))
  end do
  do i = 1, nn
    read (10, *) nop(i), nl(i), nr_(i), npr(i)
  end do
  do i = 1, nr
    read (10, *) roots(i)
  end do
  tmerge = 1.0e-9_qp * s
  fwd = look - eye
  fwd = fwd / sqrt(sum(fwd**2))
  rt = cross(fwd, up)
  rt = rt / sqrt(sum(rt**2))
  uu = cross(rt, fwd)
  th = tan(fov / 2 * acos(-1.0_qp) / 180)
  asp = real(w, qp) / real(h, qp)
  do y = 0, h - 1
    do x = 0, w - 1
      sx = (2 * (x + 0.5_qp) / w - 1) * th * asp
      sy = (1 - 2 * (y + 0.5_qp) / h) * th
      d = fwd + sx * rt + sy * uu
      d = d / sqrt(sum(d**2))
      call pixel(d)
    end do
  end do
  close (11)

contains

  function cross(a, b) result(c)
    real(qp), intent(in) :: a(3), b(3)
    real(qp) :: c(3)
    c(1) = a(2)*b(3) - a(3)*b(2)
    c(2) = a(3)*b(1) - a(1)*b(3)
    c(3) = a(1)*b(2) - a(2)*b(1)
  end function

  ! One pixel: nearest surface over all objects, written as a record.
  subroutine pixel(d)
    real(qp), intent(in) :: d(3)
    real(qp) :: a(maxs), b(maxs), u, v, c, win
    integer :: pa(maxs), fa(maxs), pb(maxs), fb(maxs), n, r, m, flags
    bt = big
    bp = -1
    bf = -1
    be = 0
    nends = 0
    ngraze = 0
    do r = 1, nr
      call eval(roots(r) + 1, d, a, pa, fa, b, pb, fb, n)
      do m = 1, n
        if (a(m) > 0 .and. fa(m) >= 0) then
          call consider(a(m), pa(m), fa(m), 1)
          exit
        end if
        if (b(m) > 0 .and. fb(m) >= 0) then
          call consider(b(m), pb(m), fb(m), 0)
          exit
        end if
      end do
    end do
    flags = 0
    u = 0
    v = 0
    if (bp >= 0) then
      call surface(bp + 1, bf, d, u, v, c)
      ! the modes' error grows with the distance from where a primary ray
      ! starts (at the scene, docs/numerics.md), not from the eye
      win = 1.6e-4_qp * s / max(c, 0.05_qp)
      if (c < 0.05_qp) flags = 1
      do m = 1, nends
        if (abs(ends(m) - bt) > tmerge .and. abs(ends(m) - bt) < win) flags = 1
      end do
    end if
    do m = 1, ngraze
      if (grazes(m) > 0 .and. (bp < 0 .or. grazes(m) <= bt)) flags = 1
    end do
    write (11) int(bp, 4), int(bf, 4), int(flags, 4), real(bt, dp) * merge(1, -1, bp >= 0), &
      real(u, dp), real(v, dp)
  end subroutine

  subroutine consider(t, p, f, entering)
    real(qp), intent(in) :: t
    integer, intent(in) :: p, f, entering
    if (t < bt - tmerge .or. (abs(t - bt) <= tmerge .and. (entering > be .or. &
        (entering == be .and. p < bp)))) then
      bt = t
      bp = p
      bf = f
      be = entering
    end if
  end subroutine

  ! Span list of node k (1-based) along eye + t d: spans [a, b) with the
  ! primitive and face of each end.
  recursive subroutine eval(k, d, a, pa, fa, b, pb, fb, n)
    integer, intent(in) :: k
    real(qp), intent(in) :: d(3)
    real(qp), intent(out) :: a(maxs), b(maxs)
    integer, intent(out) :: pa(maxs), fa(maxs), pb(maxs), fb(maxs), n
    real(qp) :: la(maxs), lb(maxs), ra(maxs), rb(maxs)
    integer :: lpa(maxs), lfa(maxs), lpb(maxs), lfb(maxs), rpa(maxs), rfa(maxs), rpb(maxs), rfb(maxs)
    integer :: ln, rn
    if (nop(k) == 0) then
      call span(npr(k) + 1, d, a(1), fa(1), b(1), fb(1), n)
      pa(1) = npr(k)
      pb(1) = npr(k)
      return
    end if
    call eval(nl(k) + 1, d, la, lpa, lfa, lb, lpb, lfb, ln)
    call eval(nr_(k) + 1, d, ra, rpa, rfa, rb, rpb, rfb, rn)
    call merge_spans(nop(k), la, lpa, lfa, lb, lpb, lfb, ln, ra, rpa, rfa, rb, rpb, rfb, rn, &
                     a, pa, fa, b, pb, fb, n)
  end subroutine

  ! Sweep over the boundaries of two span lists; boundaries within tmerge
  ! are one boundary, and of those the lower primitive's end is kept.
  subroutine merge_spans(op, la, lpa, lfa, lb, lpb, lfb, ln, ra, rpa, rfa, rb, rpb, rfb, rn, &
                         a, pa, fa, b, pb, fb, n)
    integer, intent(in) :: op, ln, rn
    real(qp), intent(in) :: la(maxs), lb(maxs), ra(maxs), rb(maxs)
    integer, intent(in) :: lpa(maxs), lfa(maxs), lpb(maxs), lfb(maxs), rpa(maxs), rfa(maxs), rpb(maxs), rfb(maxs)
    real(qp), intent(out) :: a(maxs), b(maxs)
    integer, intent(out) :: pa(maxs), fa(maxs), pb(maxs), fb(maxs), n
    integer :: i, j, inl, inr, inres, now, ep, ef
    real(qp) :: t, tl, tr, et
    i = 1; j = 1; inl = 0; inr = 0; inres = 0; n = 0
    do while (i <= ln .or. j <= rn)
      tl = big * 10
      tr = big * 10
      if (i <= ln) tl = merge(lb(i), la(i), inl == 1)
      if (j <= rn) tr = merge(rb(j), ra(j), inr == 1)
      t = min(tl, tr)
      ep = huge(1)
      ef = -1
      et = t
      call take(t + tmerge, la, lpa, lfa, lb, lpb, lfb, ln, i, inl, ep, ef, et)
      call take(t + tmerge, ra, rpa, rfa, rb, rpb, rfb, rn, j, inr, ep, ef, et)
      select case (op)
      case (1)
        now = merge(1, 0, inl == 1 .or. inr == 1)
      case (2)
        now = merge(1, 0, inl == 1 .and. inr == 1)
      case default
        now = merge(1, 0, inl == 1 .and. inr == 0)
      end select
      if (now == inres) cycle
      if (ep == huge(1)) ep = -1
      if (now == 1) then
        if (n >= maxs) exit
        n = n + 1
        a(n) = et; pa(n) = ep; fa(n) = ef
      else
        b(n) = et; pb(n) = ep; fb(n) = ef
      end if
      inres = now
    end do
  end subroutine

  ! Consumes the boundaries of one list up to lim (cursor i, state inside),
  ! keeping the end that merge_spans reports.
  subroutine take(lim, a, pa, fa, b, pb, fb, n, i, inside, ep, ef, et)
    real(qp), intent(in) :: lim, a(maxs), b(maxs)
    integer, intent(in) :: pa(maxs), fa(maxs), pb(maxs), fb(maxs), n
    integer, intent(inout) :: i, inside, ep, ef
    real(qp), intent(inout) :: et
    do while (i <= n)
      if (merge(b(i), a(i), inside == 1) > lim) exit
      if (inside == 1) then
        call keep(pb(i), fb(i), b(i), ep, ef, et)
        inside = 0
        i = i + 1
      else
        call keep(pa(i), fa(i), a(i), ep, ef, et)
        inside = 1
      end if
    end do
  end subroutine

  subroutine keep(p, f, t, ep, ef, et)
    integer, intent(in) :: p, f
    real(qp), intent(in) :: t
    integer, intent(inout) :: ep, ef
    real(qp), intent(inout) :: et
    if (p >= 0 .and. (ep == huge(1) .or. ep < 0 .or. p < ep)) then
      ep = p; ef = f; et = t
    else if (ep == huge(1)) then
      ep = p; ef = f; et = t
    end if
  end subroutine

  ! Span of primitive i along eye + t d: n = 1 and [t0, t1) with faces, or 0.
  subroutine span(i, d, t0, f0, t1, f1, n)
    integer, intent(in) :: i
    real(qp), intent(in) :: d(3)
    real(qp), intent(out) :: t0, t1
    integer, intent(out) :: f0, f1, n
    real(qp) :: q(3), e(3), k, r, rv, qa, qb, qc, disc, x0, x1
    logical :: hit
    integer :: j
    q = matmul(inv(:, :, i), eye - mat(:, 4, i))
    e = matmul(inv(:, :, i), d)
    t0 = -big; t1 = big; f0 = -1; f1 = -1; hit = .true.
    nc0 = nends
    nc = nends
    grr = maxval(dims(:, i))
    select case (pkind(i))
    case (0)
      call quadric(sum(e**2), sum(q*e), sum(q**2) - dims(1, i)**2, 0, t0, f0, t1, f1, hit)
    case (1)
      call slab(q(3), e(3), 0.0_qp, dims(2, i), 2, 1, t0, f0, t1, f1, hit)
      if (hit) call quadric(e(1)**2 + e(2)**2, q(1)*e(1) + q(2)*e(2), &
                            q(1)**2 + q(2)**2 - dims(1, i)**2, 0, t0, f0, t1, f1, hit)
    case (2)
      do j = 1, 3
        if (hit) call slab(q(j), e(j), 0.0_qp, dims(j, i), 2*j - 2, 2*j - 1, t0, f0, t1, f1, hit)
      end do
    case (3)
      call slab(q(3), e(3), 0.0_qp, dims(3, i), 2, 1, t0, f0, t1, f1, hit)
      if (hit) then
        k = (dims(2, i) - dims(1, i)) / dims(3, i)
        r = dims(1, i) + k*q(3)
        rv = k*e(3)
        qa = e(1)**2 + e(2)**2 - rv*rv
        qb = q(1)*e(1) + q(2)*e(2) - r*rv
        qc = q(1)**2 + q(2)**2 - r*r
        if (qa > 0) then
          call quadric(qa, qb, qc, 0, t0, f0, t1, f1, hit)
        else if (qa < 0) then
          disc = qb*qb - qa*qc
          if (disc >= 0) then
            x0 = (-qb + sqrt(disc)) / qa
            x1 = (-qb - sqrt(disc)) / qa
            if (t0 < min(t1, x0)) then
              if (x0 < t1) then
                t1 = x0; f1 = 0
              end if
            else if (max(t0, x1) < t1) then
              if (x1 > t0) then
                t0 = x1; f0 = 0
              end if
            else
              hit = .false.
            end if
          end if
        else if (qb /= 0) then
          if (qb > 0 .and. -qc / (2*qb) < t1) then
            t1 = -qc / (2*qb); f1 = 0
          else if (qb < 0 .and. -qc / (2*qb) > t0) then
            t0 = -qc / (2*qb); f0 = 0
          end if
        else if (qc > 0) then
          hit = .false.
        end if
      end if
    case default
      call slab(q(3), e(3), -big, 0.0_qp, -1, 0, t0, f0, t1, f1, hit)
    end select
    n = 0
    if (hit .and. t0 < t1) then
      n = 1
    else if (abs(t0) < big / 10 .and. abs(t1) < big / 10 .and. t0 >= t1 .and. &
             t0 - t1 < 1.6e-4_qp * s) then
      call graze(t0)                    ! just past an edge: a near miss
    end if
    nends = nc
    if (n == 0) nends = nc0
  end subroutine

  subroutine graze(t)
    real(qp), intent(in) :: t
    if (ngraze < maxs) then
      ngraze = ngraze + 1
      grazes(ngraze) = t
    end if
  end subroutine

  ! Records a candidate boundary (a face crossing) of the primitive being
  ! clipped; kept only when its span is not empty.
  subroutine cand(t)
    real(qp), intent(in) :: t
    if (nc < size(ends) .and. abs(t) < big / 10) then
      nc = nc + 1
      ends(nc) = t
    end if
  end subroutine

  ! Clips [t0,t1] to lo <= p + t v <= hi; flo/fhi name the faces there.
  subroutine slab(p, v, lo, hi, flo, fhi, t0, f0, t1, f1, hit)
    real(qp), intent(in) :: p, v, lo, hi
    integer, intent(in) :: flo, fhi
    real(qp), intent(inout) :: t0, t1
    integer, intent(inout) :: f0, f1
    logical, intent(inout) :: hit
    real(qp) :: a, b
    integer :: fa, fb
    if (v == 0) then
      if (p < lo .or. p > hi) hit = .false.
      return
    end if
    a = (lo - p) / v
    b = (hi - p) / v
    call cand(a)
    call cand(b)
    fa = flo
    fb = fhi
    if (a > b) then
      call swap(a, b, fa, fb)
    end if
    if (abs(a) < big / 10 .and. a > t0) then
      t0 = a; f0 = fa
    end if
    if (abs(b) < big / 10 .and. b < t1) then
      t1 = b; f1 = fb
    end if
    if (t0 >= t1) hit = .false.
  end subroutine

  subroutine swap(a, b, fa, fb)
    real(qp), intent(inout) :: a, b
    integer, intent(inout) :: fa, fb
    real(qp) :: t
    integer :: f
    t = a; a = b; b = t
    f = fa; fa = fb; fb = f
  end subroutine

  ! Clips [t0,t1] to A t^2 + 2 B t + C <= 0 with A >= 0 (face f).
  subroutine quadric(qa, qb, qc, f, t0, f0, t1, f1, hit)
    real(qp), intent(in) :: qa, qb, qc
    integer, intent(in) :: f
    real(qp), intent(inout) :: t0, t1
    integer, intent(inout) :: f0, f1
    logical, intent(inout) :: hit
    real(qp) :: disc, r0, r1
    if (qa == 0) then
      if (qc > 0) hit = .false.
      return
    end if
    disc = qb*qb - qa*qc
    if (disc < 0) then
      ! within the window of tangency: a near miss at the tangent point
      ! (-disc/qa is the squared miss distance less r^2 for a sphere or
      ! cylinder; a cone's is taken the same way with its larger radius)
      if (-disc / qa < 2 * grr * 4.0e-5_qp * s) call graze(-qb / qa)
      hit = .false.
      return
    end if
    r0 = (-qb - sqrt(disc)) / qa
    r1 = (-qb + sqrt(disc)) / qa
    call cand(r0)
    call cand(r1)
    if (r0 > t0) then
      t0 = r0; f0 = f
    end if
    if (r1 < t1) then
      t1 = r1; f1 = f
    end if
    if (t0 >= t1) hit = .false.
  end subroutine

  ! (u,v) of face f of primitive i at the hit bt (docs/primitives.md) and
  ! |cos| of the angle between the ray and the face normal.
  subroutine surface(i, f, d, u, v, c)
    integer, intent(in) :: i, f
    real(qp), intent(in) :: d(3)
    real(qp), intent(out) :: u, v, c
    real(qp) :: q(3), nl(3), nw(3), pi2, thet, rho, kk, rf, x, yy, z
    integer :: j
    pi2 = 2 * acos(-1.0_qp)
    q = matmul(inv(:, :, i), eye + bt * d - mat(:, 4, i))
    x = q(1); yy = q(2); z = q(3)
    rho = sqrt(x*x + yy*yy)
    thet = atan2(yy, x)
    if (thet < 0) thet = thet + pi2
    nl = 0
    u = 0
    v = 0
    select case (pkind(i))
    case (0)
      u = thet / pi2
      v = 0.5_qp + atan2(z, rho) / (pi2 / 2)
      nl = q
    case (1, 3)
      if (pkind(i) == 1) then
        kk = 0
        rf = dims(1, i)
      else
        kk = (dims(2, i) - dims(1, i)) / dims(3, i)
      end if
      if (f == 0) then
        u = thet / pi2
        v = z / dims(merge(2, 3, pkind(i) == 1), i)
        nl = (/ x, yy, -kk * rho /)
      else
        if (pkind(i) == 1) then
          rf = dims(1, i)
        else
          rf = merge(dims(2, i), dims(1, i), f == 1)
        end if
        if (rf <= 0) then
          u = 0.5_qp; v = 0.5_qp
        else if (f == 1) then
          u = (x / rf + 1) / 2; v = (yy / rf + 1) / 2
        else
          u = (1 - x / rf) / 2; v = (yy / rf + 1) / 2
        end if
        nl(3) = merge(1, -1, f == 1)
      end if
    case (2)
      x = x / dims(1, i); yy = yy / dims(2, i); z = z / dims(3, i)
      select case (f)
      case (0)
        u = 1 - yy; v = z; nl(1) = -1
      case (1)
        u = yy; v = z; nl(1) = 1
      case (2)
        u = x; v = z; nl(2) = -1
      case (3)
        u = 1 - x; v = z; nl(2) = 1
      case (4)
        u = 1 - x; v = yy; nl(3) = -1
      case default
        u = x; v = yy; nl(3) = 1
      end select
    case default
      u = x - floor(x)
      v = yy - floor(yy)
      nl(3) = 1
    end select
    u = min(max(u, 0.0_qp), 1.0_qp)
    v = min(max(v, 0.0_qp), 1.0_qp)
    do j = 1, 3
      nw(j) = sum(inv(:, j, i) * nl)
    end do
    c = abs(sum(nw * d)) / max(sqrt(sum(nw**2)), tiny(1.0_qp))
  end subroutine
end program
