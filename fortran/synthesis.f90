! synthesis.f90 -- placeholder, filled in by the chapter's work.
module synthesis
  use prmtr, only: dp
  implicit none
  private
  public :: synthesis_placeholder
contains
  subroutine synthesis_placeholder(x)
    real(dp), intent(inout) :: x
    x = x
  end subroutine synthesis_placeholder
end module synthesis
