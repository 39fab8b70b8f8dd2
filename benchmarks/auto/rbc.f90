!------------------------------------------------------------------------------
! rbcstab benchmark: Fig. 2's in-plane reduced system (lambda = 5, Delta0 = 0.01, B = 2, C = 0.04,
! beta = pi/2) as a periodically forced system, made autonomous with AUTO's usual forcing oscillator
! (U4, U5) = (sin t, cos t), continued in PAR(1) = Delta. y = (Re z, Im z, w) on |y| = 1:
!   y' = mu y + (-y2, y1, 0) + F(t) + (1 - |y|^2) y,   mu = -(y.F)/|y|^2,
!   F = s (kz0 e^{it}, -1/Lambda, kappa w0) (real and imaginary parts of the first component),
! s = sqrt(0.05/Delta) (1/Lambda and kappa both scale as Delta^{-1/2}). The term (1 - |y|^2) y vanishes on
! the sphere and makes it attracting, removing the family of orbits on the other spheres (rbcstab solves
! the same degeneracy with its |x_0|^2 closing term). The constants are rbcstab's at Delta = 0.05,
! read from rbcstab.rhs by benchmarks/auto/compare.py.
!------------------------------------------------------------------------------
      SUBROUTINE FUNC(NDIM,U,ICP,PAR,IJAC,F,DFDU,DFDP)
      IMPLICIT NONE
      INTEGER, INTENT(IN) :: NDIM, ICP(*), IJAC
      DOUBLE PRECISION, INTENT(IN) :: U(NDIM), PAR(*)
      DOUBLE PRECISION, INTENT(OUT) :: F(NDIM)
      DOUBLE PRECISION, INTENT(INOUT) :: DFDU(NDIM,NDIM), DFDP(NDIM,*)
      DOUBLE PRECISION KZR, KZI, INVL, KW, S, Q, YF, MU, SS, FF(3), DF4(3), DF5(3), DMU(3), DM4, DM5
      INTEGER I, J
      KZR = PAR(2); KZI = PAR(3); INVL = PAR(4); KW = PAR(5)
      S = SQRT(0.05D0 / PAR(1))
      FF(1) = S * (KZR * U(5) - KZI * U(4))
      FF(2) = S * (KZR * U(4) + KZI * U(5)) - S * INVL
      FF(3) = S * KW
      Q = U(1)**2 + U(2)**2 + U(3)**2
      YF = U(1) * FF(1) + U(2) * FF(2) + U(3) * FF(3)
      MU = -YF / Q
      DO I = 1, 3
        F(I) = (MU + 1 - Q) * U(I) + FF(I)
      END DO
      F(1) = F(1) - U(2)
      F(2) = F(2) + U(1)
      SS = U(4)**2 + U(5)**2
      F(4) = U(4) + U(5) - U(4) * SS
      F(5) = -U(4) + U(5) - U(5) * SS
      IF (IJAC == 0) RETURN
      DF4 = (/ -S * KZI, S * KZR, 0D0 /)
      DF5 = (/ S * KZR, S * KZI, 0D0 /)
      DO J = 1, 3
        DMU(J) = -FF(J) / Q + 2 * YF * U(J) / Q**2
      END DO
      DM4 = -(U(1) * DF4(1) + U(2) * DF4(2)) / Q
      DM5 = -(U(1) * DF5(1) + U(2) * DF5(2)) / Q
      DFDU = 0
      DO I = 1, 3
        DO J = 1, 3
          DFDU(I, J) = U(I) * DMU(J) - 2 * U(I) * U(J)
        END DO
        DFDU(I, I) = DFDU(I, I) + MU + 1 - Q
        DFDU(I, 4) = U(I) * DM4 + DF4(I)
        DFDU(I, 5) = U(I) * DM5 + DF5(I)
      END DO
      DFDU(1, 2) = DFDU(1, 2) - 1
      DFDU(2, 1) = DFDU(2, 1) + 1
      DFDU(4, 4) = 1 - SS - 2 * U(4)**2
      DFDU(4, 5) = 1 - 2 * U(4) * U(5)
      DFDU(5, 4) = -1 - 2 * U(4) * U(5)
      DFDU(5, 5) = 1 - SS - 2 * U(5)**2
      IF (IJAC == 1) RETURN
      DFDP(:, 1) = 0
      DO I = 1, 3
        DFDP(I, 1) = -(MU * U(I) + FF(I)) / (2 * PAR(1))
      END DO
      END SUBROUTINE FUNC

      SUBROUTINE STPNT(NDIM,U,PAR,T)
      IMPLICIT NONE
      INTEGER, INTENT(IN) :: NDIM
      DOUBLE PRECISION, INTENT(INOUT) :: U(NDIM),PAR(*)
      DOUBLE PRECISION, INTENT(IN) :: T
      END SUBROUTINE STPNT

      SUBROUTINE BCND
      END SUBROUTINE BCND

      SUBROUTINE ICND
      END SUBROUTINE ICND

      SUBROUTINE FOPT
      END SUBROUTINE FOPT

      SUBROUTINE PVLS
      END SUBROUTINE PVLS
