"""Citations used in the ball-clutch reports, in one place.

Seed 003: V. O. Malashchenko, V. F. Semenyuk, A. O. Boris, B. R. Lysiak, "Improved performance
of drives with ball overrunning clutches" (2025); equations as decoded in the method note
``worm_wave_clutch_geneva.md`` section C (eqs. (5), (8), (10)-(15) are reconstructed there).
"""

SEED_EQ1_4 = "seed 003 eqs. (1)-(4)"
SEED_EQ7 = "seed 003 eq. (7)"
SEED_EQ15 = "seed 003 eq. (15)"
FRICTION = "seed 003 eq. (15) with friction (Ivanov-type)"
CENTRIFUGAL = "seed 003 eqs. (10), (15) (centrifugal term)"
SPRING = "helical spring (Wahl); GOST 13765-86"
SPRING_ENDS = "helical spring ends (Shigley Table 10-1)"
MATERIAL = "spring steel table (Shigley Tables 10-4..10-6)"
HERTZ = "Hertz point contact (Johnson 1985, §4.2)"
ISO76 = "ISO 76 (4 200 MPa ball contact)"
PRACTICE = "design practice"
