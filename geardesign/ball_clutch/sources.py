"""Citations used in the ball-clutch reports, in one place.

[Malashchenko2025]: V. O. Malashchenko, V. F. Semenyuk, A. O. Boris, B. R. Lysiak, "Improved performance
of drives with ball overrunning clutches" (2025); equation numbers as in the paper (eqs. (5), (8),
(10)-(15) are reconstructed in docs/ball_clutch.md).
"""

SEED_EQ1_4 = "[Malashchenko2025] eqs. (1)-(4)"
SEED_EQ7 = "[Malashchenko2025] eq. (7)"
SEED_EQ15 = "[Malashchenko2025] eq. (15)"
FRICTION = "[Malashchenko2025] eq. (15) with friction (Ivanov-type)"
CENTRIFUGAL = "[Malashchenko2025] eqs. (10), (15) (centrifugal term)"
SPRING = "helical spring (Wahl); GOST 13765-86"
SPRING_ENDS = "helical spring ends (Shigley Table 10-1)"
MATERIAL = "spring steel table (Shigley Tables 10-4..10-6)"
HERTZ = "Hertz point contact (Johnson 1985, §4.2)"
ISO76 = "ISO 76 (4 200 MPa ball contact)"
PRACTICE = "design practice"
