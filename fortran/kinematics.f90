! kinematics.f90 -- placeholder, filled in by the chapter's work.
module kinematics
  use prmtr, only: dp
  implicit none
  private
  public :: kinematics_placeholder
contains
  subroutine kinematics_placeholder(x)
    real(dp), intent(inout) :: x
    x = x
  end subroutine kinematics_placeholder
end module kinematics
