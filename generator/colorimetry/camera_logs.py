"""Camera log curves that are exactly OCIO's LogCamera: each computed from the constants
its vendor prints (the conventions are in :mod:`generator.colorimetry.curves`).

OCIO's LogCamera puts its straight segment through the log segment's value at
the break. Where a vendor prints its own toe offset as well as its slope, the
two can disagree by the rounding of the printed constants; the step
(vendor toe minus log segment, at the break, in code value) is given in each
function's notes.
"""

from __future__ import annotations

import math

from generator.colorimetry.transfer import LogCamera


def acescct() -> LogCamera:
    """ACEScct: ``(log2(x) + 9.72) / 17.52`` above ``x = 2**-7``.

    The printed toe (slope 10.5402377416545, offset 0.0729055341958355) is the
    tangent at the break, so the derivative-continuous default is exact.

    References
    ----------
    Academy of Motion Picture Arts and Sciences (2016). S-2016-001, *ACEScct*.
    """
    return LogCamera(2.0, 1.0 / 17.52, 9.72 / 17.52, 1.0, 0.0, lin_side_break=2.0**-7)


def arri_logc3_ei800() -> LogCamera:
    """ARRI LogC3 (ALEXA SUP 3.x), EI 800: ``c * log10(a x + b) + d`` above ``cut``.

    The printed toe ``e x + f`` (e = 5.367655, f = 0.092809) sits 2.5e-7 in
    code above the log segment at the break.

    References
    ----------
    ARRI (2017). *ALEXA Log C Curve – Usage in VFX*, table for SUP 3.x, EI 800.
    """
    cut, a, b, c, d, e = 0.010591, 5.555556, 0.052272, 0.247190, 0.385537, 5.367655
    return LogCamera(10.0, c, d, a, b, lin_side_break=cut, linear_slope=e)


def arri_logc4() -> LogCamera:
    """ARRI LogC4: ``(log2(a x + 64) - 6) / 14 * b + c`` above ``t``, ``(x - t) / s`` below.

    ``a = (2**18 - 16) / 117.45``, ``b = (1023 - 95) / 1023``, ``c = 95 / 1023``;
    ``t`` is where the log segment reaches code 0 and ``s`` makes the slope
    continuous there.

    References
    ----------
    ARRI (2022). *ARRI LogC4 Logarithmic Color Space Specification*.
    """
    a = (2.0**18 - 16.0) / 117.45
    b = (1023.0 - 95.0) / 1023.0
    c = 95.0 / 1023.0
    s = 7.0 * math.log(2.0) * 2.0 ** (7.0 - 14.0 * c / b) / (a * b)
    t = (2.0 ** (14.0 * -c / b + 6.0) - 64.0) / a
    return LogCamera(2.0, b / 14.0, c - 6.0 * b / 14.0, a, 64.0, lin_side_break=t, linear_slope=1.0 / s)


def sony_slog3() -> LogCamera:
    """Sony S-Log3: ``(420 + 261.5 log10((x + 0.01) / (0.18 + 0.01))) / 1023`` above 0.01125.

    The printed toe, a line from code 95 at x = 0 to code 171.2102946929 at the
    break, meets the log segment there to 4e-14; its slope is its own
    (6.62 against the log segment's 5.22).

    References
    ----------
    Sony Corporation. *Technical Summary for S-Gamut3.Cine/S-Log3 and
    S-Gamut3/S-Log3*.
    """
    cut, toe_slope = 0.01125, (171.2102946929 - 95.0) / 0.01125 / 1023.0
    return LogCamera(10.0, 261.5 / 1023.0, 420.0 / 1023.0, 1.0 / 0.19, 0.01 / 0.19, cut, toe_slope)


def red_log3g10() -> LogCamera:
    """RED Log3G10 (the current, "v3", curve): ``a log10((x + c) b + 1)`` above ``x = -c``.

    Below the break, ``g (x + c)``; both segments are 0 at the break.

    References
    ----------
    RED Digital Cinema. *White Paper on REDWideGamutRGB and Log3G10*
    (915-0187 Rev-C).
    """
    a, b, c, g = 0.224282, 155.975327, 0.01, 15.1927
    return LogCamera(10.0, a, 0.0, b, b * c + 1.0, lin_side_break=-c, linear_slope=g)


def panasonic_vlog() -> LogCamera:
    """Panasonic V-Log: ``c log10(x + b) + d`` above 0.01, ``5.6 x + 0.125`` below.

    The printed toe sits 3.1e-7 in code above the log segment at the break.

    References
    ----------
    Panasonic (2014). *VARICAM V-Log/V-Gamut*.
    """
    b, c, d = 0.00873, 0.241514, 0.598206
    return LogCamera(10.0, c, d, 1.0, b, lin_side_break=0.01, linear_slope=5.6)


def blackmagic_film_gen5() -> LogCamera:
    """Blackmagic Film Generation 5: ``A ln(x + B) + C`` above 0.005, ``D x + E`` below.

    The printed toe meets the log segment to 1e-16 (the constants are given to
    full double precision).

    References
    ----------
    Blackmagic Design (2021). *Blackmagic Generation 5 Color Science*,
    technical reference in the Blackmagic RAW SDK.
    """
    A, B, C, D = 0.08692876065491224, 0.005494072432257808, 0.5300133392291939, 8.283605932402494
    return LogCamera(math.e, A, C, 1.0, B, lin_side_break=0.005, linear_slope=D)


def davinci_intermediate() -> LogCamera:
    """DaVinci Intermediate: ``(log2(x + A) + B) C`` above 0.00262409, ``M x`` below.

    The printed toe (through the origin) sits 3.4e-10 in code above the log
    segment at the break.

    References
    ----------
    Blackmagic Design (2021). *DaVinci Resolve 17 Wide Gamut Intermediate*.
    """
    A, B, C, M, cut = 0.0075, 7.0, 0.07329248, 10.44426855, 0.00262409
    return LogCamera(2.0, C, B * C, 1.0, A, lin_side_break=cut, linear_slope=M)


def dji_dlog() -> LogCamera:
    """DJI D-Log: ``0.256663 log10(0.9892 x + 0.0108) + 0.584555`` above 0.0078.

    The printed toe ``6.025 x + 0.0929`` sits 2.0e-6 in code below the log
    segment at the break. The paper's decoding formula uses rounded
    reciprocals (3.89616, 2.27752); ours is the exact inverse of the encoding.

    References
    ----------
    DJI (2017). *D-Log and D-Gamut White Paper*.
    """
    return LogCamera(10.0, 0.256663, 0.584555, 0.9892, 0.0108, lin_side_break=0.0078, linear_slope=6.025)


def fujifilm_flog() -> LogCamera:
    """Fujifilm F-Log: ``c log10(a x + b) + d`` above ``cut1``, ``e x + f`` below.

    The printed toe ``8.735631 x + 0.092864`` sits 1.0e-4 in code (0.1 of a
    10-bit code) above the log segment at the break, the largest step of the
    curves here.

    References
    ----------
    Fujifilm (2016). *F-Log Data Sheet* Ver.1.0.
    """
    return LogCamera(10.0, 0.344676, 0.790453, 0.555556, 0.009468, 0.00089, 8.735631)


def fujifilm_flog2() -> LogCamera:
    """Fujifilm F-Log2: the F-Log form with its own constants.

    The printed toe ``8.799461 x + 0.092864`` sits 3.5e-8 in code above the
    log segment at the break.

    References
    ----------
    Fujifilm (2022). *F-Log2 Data Sheet* Ver.1.0.
    """
    return LogCamera(10.0, 0.245281, 0.384316, 5.555556, 0.064829, 0.000889, 8.799461)


def leica_llog() -> LogCamera:
    """Leica L-Log: ``0.27 log10(1.3 x + 0.0115) + 0.6`` above 0.006, ``8 x + 0.09`` below.

    The printed toe is noticeably discontinuous: at the break it sits 9.0e-4
    in code (0.9 of a 10-bit code) above the log segment. We keep the printed
    slope 8 and move the toe down onto the log segment; the printed decoding
    switches at code 0.138, ours at the log segment's 0.1371.

    References
    ----------
    Leica Camera AG (2023). *Leica L-Log Reference Manual* v1.4, section 3.1.
    """
    return LogCamera(10.0, 0.27, 0.6, 1.3, 0.0115, lin_side_break=0.006, linear_slope=8.0)


def _filmlight_tlog(w: float, g: float, o: float) -> LogCamera:
    """FilmLight T-Log family, ``A + B ln(x + C)`` above 0 and ``G x + o`` below.

    ``w`` is the linear value encoded as 1.0, ``g`` the intended gradient at
    0 and ``o`` the code of linear 0. FilmLight derives A, B, C and G with an
    approximate solution (their words: the gradient is within a few percent
    of ``g``); G is exactly the log segment's slope at 0, so the toe is the
    tangent and needs no explicit slope.
    """
    b = 1.0 / (0.7107 + 1.2359 * math.log(w * g))
    gs = g / (1.0 - o)
    C = b / gs
    a = 1.0 - b * math.log(w + C)
    y0 = a + b * math.log(C)
    s = (1.0 - o) / (1.0 - y0)
    A = 1.0 + (a - 1.0) * s
    B = b * s
    return LogCamera(math.e, B, A, 1.0, C, lin_side_break=0.0)


def filmlight_tlog() -> LogCamera:
    """FilmLight T-Log: w = 128, g = 16, o = 0.075.

    References
    ----------
    FilmLight (2018). ``FilmLight_TLog_EGamut.flspace``, Baselight 5
    colour space file (T-Log "Version 10.0"), as quoted in colour-science.
    """
    return _filmlight_tlog(128.0, 16.0, 0.075)


def filmlight_tloge() -> LogCamera:
    """FilmLight T-LogE: the T-Log construction with w = 512 (g = 16, o = 0.075).

    No FilmLight document defining T-LogE was found; w = 512 is the value
    public implementations use for it. Treat as provisional.
    """
    return _filmlight_tlog(512.0, 16.0, 0.075)


def jplog2() -> LogCamera:
    """JPLog2: 50 ten-bit codes per stop, linear 1.0 at code 525, toe below code 165.

    ``code = (log2(x) + 10.5) / 20.46`` (20.46 = 1023 / 50) above the break
    ``x = 2 ** ((165 - 525) / 50) = 2 ** -7.2``; below it the published line
    (slope 10.36773919972907, offset 0.09077750069969258), which passes
    through the break point to 3e-12 but is 1.9e-6 (relative) shallower than
    the tangent.

    References
    ----------
    Pines, J. (2020). JPLog2, contributed to the ACES "ACESlog" virtual working
    group (ACEScentral, "ACESLog Strawman Proposal").
    """
    per_stop, code_at_one, break_code = 50.0 / 1023.0, 525.0 / 1023.0, 165.0 / 1023.0
    brk = 2.0 ** ((break_code - code_at_one) / per_stop)
    return LogCamera(2.0, per_stop, code_at_one, 1.0, 0.0, lin_side_break=brk, linear_slope=10.36773919972907)
