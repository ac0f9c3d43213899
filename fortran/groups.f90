! groups.f90 -- one home for each Assur group kind (issue 25).
!
! Each kind -- the crank, a rigid point, and the book's dyads 1-5 (RRR, RRP, RPR, PRP, RPP)
! -- has its kernels here and nowhere else: positions, velocities, accelerations with the
! error estimates of the dead-centre policy (numerics.f90), and the chapter 7 force step.
! The kernels take and return named Cartesian quantities of one position.  Their callers:
! mechanism.f90 (sarkp.Mechanism, a whole mechanism in one call) and the book's routines,
! DPRM/DSKOR/DUSKR/DKNMA 1-5 (kinematics.f90) and DNMA/DNMAF 1-5 (forces.f90), adapters that
! keep the book's conventions (polar hand-offs, branch signs, argument order).
! A new kind is one kernel here plus its declaration in python/sarkp/mechanism.py.
module groups
  use prmtr, only: dp, st_ok, st_assembly, st_singular, st_range, norm2d
  use numerics, only: uround, bound2
  implicit none
  private

contains

  ! =====================================================================================
  ! Kinematics: positions, velocities, accelerations, error estimates
  ! =====================================================================================

  ! =====================================================================================
  ! The chapter 7 force step: a group's pair reactions from its links' loads
  ! =====================================================================================

end module groups
