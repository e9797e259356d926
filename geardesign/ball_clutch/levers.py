"""Levers of the ball-clutch advice (:mod:`geardesign.core.advice`), each re-rated: a
socket that self-locks gets the largest angle below the locking one
(``safety.socket_angle``, 0.1° steps); a clutch that trips at the rated torque or releases
by speed gets a larger spring preload (``spring.preload``, 5 % steps up to three times);
a spring that goes solid a longer free length (``spring.free_length``, 2 % steps); an
overloaded ball contact more balls (``safety.balls``, one at a time up to twice)."""

from __future__ import annotations

from geardesign.core.advice import Lever, scaled, to_limit


def _more_balls(data: dict, _res):
    z = (data.get("safety") or {}).get("balls")
    if isinstance(z, int) and not isinstance(z, bool):
        for n in range(z + 1, 2 * z + 1):
            yield (("safety.balls", n),)


LEVERS = (
    Lever(("SELF_LOCKING",), to_limit("SELF_LOCKING", "safety.socket_angle", up=False),
          "the largest socket angle that does not self-lock"),
    Lever(("LIMIT_ABOVE_RATED", "CENTRIFUGAL_RELEASE"),
          scaled("spring.preload", [1.0 + 0.05 * i for i in range(1, 41)], 2),
          "a larger spring preload"),
    Lever(("SPRING_SOLID",), scaled("spring.free_length", [1.0 + 0.02 * i for i in range(1, 26)],
                                    1), "a longer free length"),
    Lever(("BALL_CONTACT",), _more_balls, "more balls on the same circle"),
)
