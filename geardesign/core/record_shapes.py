"""The ``__init__`` of every record shape of the package (:func:`geardesign.core.records.shape`),
compiled with the package.  Written by ``python -m geardesign.core.records``; do not edit (one
function a shape: longer than a module is meant to be, as it is generated)."""

# fmt: off
# ruff: noqa
SHAPES = {}

def __init__(self, _0, _1):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
SHAPES['fPP'] = __init__.__code__

def __init__(self, _0, _1):
    self._0 = _0
    self._1 = _1
SHAPES['mPP'] = __init__.__code__

def __init__(self, _0, _1, _2):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', __f_2() if _2 is __factory else _2)
SHAPES['fPPF'] = __init__.__code__

def __init__(self, _0, _1, _2):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
SHAPES['fPPP'] = __init__.__code__

def __init__(self, _0, _1, _2):
    self._0 = _0
    self._1 = _1
    self._2 = __f_2() if _2 is __factory else _2
SHAPES['mPPF'] = __init__.__code__

def __init__(self, _0, _1, _2):
    self._0 = _0
    self._1 = _1
    self._2 = _2
SHAPES['mPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
SHAPES['fPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = __f_3() if _3 is __factory else _3
SHAPES['mPPPF'] = __init__.__code__

def __init__(self, _0, _1, _2, _3):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
SHAPES['mPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
SHAPES['fKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
SHAPES['fPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4):
    self._0 = _0
    self._1 = __f_1() if _1 is __factory else _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
SHAPES['mPFPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = __f_3() if _3 is __factory else _3
    self._4 = __f_4() if _4 is __factory else _4
SHAPES['mPPPFF'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
SHAPES['mPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', __f_5() if _5 is __factory else _5)
SHAPES['fPPPPPF'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
SHAPES['fPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
SHAPES['mPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', __f_4() if _4 is __factory else _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
SHAPES['fPPPPFPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', __f_5() if _5 is __factory else _5)
    __set(self, '_6', _6)
SHAPES['fPPPPPFP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    self.__post_init__()
SHAPES['fPPPPPP+'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
SHAPES['fPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6):
    self._0 = _0
    self._1 = __f_1() if _1 is __factory else _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
SHAPES['mPFPPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
SHAPES['fKKKKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
SHAPES['fPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
    self._7 = __f_7() if _7 is __factory else _7
SHAPES['mPPPPPPPF'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
    self._7 = _7
SHAPES['mPPPPPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
SHAPES['fKKKKKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, *, _8):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
SHAPES['fPPPPPPPPK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
SHAPES['fPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = __f_4() if _4 is __factory else _4
    self._5 = __f_5() if _5 is __factory else _5
    self._6 = _6
    self._7 = _7
    self._8 = _8
SHAPES['mPPPPFFPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
    self._7 = _7
    self._8 = _8
SHAPES['mPPPPPPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
SHAPES['fKKKKKKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    self.__post_init__()
SHAPES['fPPPPPPPPP+'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
SHAPES['fPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
    self._7 = _7
    self._8 = __f_8() if _8 is __factory else _8
    self._9 = _9
SHAPES['mPPPPPPPPFP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
SHAPES['fKKKKKKKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
SHAPES['fPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = __f_3() if _3 is __factory else _3
    self._4 = __f_4() if _4 is __factory else _4
    self._5 = __f_5() if _5 is __factory else _5
    self._6 = __f_6() if _6 is __factory else _6
    self._7 = _7
    self._8 = __f_8() if _8 is __factory else _8
    self._9 = __f_9() if _9 is __factory else _9
    self._10 = __f_10() if _10 is __factory else _10
SHAPES['mPPPFFFFPFFF'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = __f_5() if _5 is __factory else _5
    self._6 = __f_6() if _6 is __factory else _6
    self._7 = _7
    self._8 = __f_8() if _8 is __factory else _8
    self._9 = __f_9() if _9 is __factory else _9
    self._10 = __f_10() if _10 is __factory else _10
SHAPES['mPPPPPFFPFFF'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
SHAPES['fPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
    self._7 = _7
    self._8 = _8
    self._9 = __f_9() if _9 is __factory else _9
    self._10 = __f_10() if _10 is __factory else _10
    self._11 = _11
SHAPES['mPPPPPPPPPFFP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
    self._7 = _7
    self._8 = _8
    self._9 = _9
    self._10 = _10
    self._11 = __f_11() if _11 is __factory else _11
SHAPES['mPPPPPPPPPPPF'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
SHAPES['fPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
    self._7 = _7
    self._8 = _8
    self._9 = _9
    self._10 = _10
    self._11 = _11
    self._12 = _12
SHAPES['mPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
SHAPES['fKKKKKKKKKKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _9, _10, _11, _12, _13, *, _8):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
SHAPES['fPPPPPPPPKPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
SHAPES['fPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
    self._7 = _7
    self._8 = _8
    self._9 = _9
    self._10 = _10
    self._11 = _11
    self._12 = _12
    self._13 = _13
SHAPES['mPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
SHAPES['fPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
SHAPES['fKKKKKKKKKKKKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
SHAPES['fPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    self.__post_init__()
SHAPES['fPPPPPPPPPPPPPPPP+'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
SHAPES['fPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
    self._7 = _7
    self._8 = _8
    self._9 = _9
    self._10 = _10
    self._11 = _11
    self._12 = _12
    self._13 = _13
    self._14 = _14
    self._15 = _15
    self._16 = _16
SHAPES['mPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
SHAPES['fKKKKKKKKKKKKKKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
SHAPES['fPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
SHAPES['fPPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
SHAPES['fPPPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
SHAPES['fPPPPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
SHAPES['fKKKKKKKKKKKKKKKKKKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
SHAPES['fPPPPPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
    self._7 = _7
    self._8 = _8
    self._9 = _9
    self._10 = _10
    self._11 = _11
    self._12 = _12
    self._13 = _13
    self._14 = _14
    self._15 = _15
    self._16 = _16
    self._17 = _17
    self._18 = _18
    self._19 = _19
    self._20 = _20
    self._21 = __f_21() if _21 is __factory else _21
SHAPES['mPPPPPPPPPPPPPPPPPPPPPF'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
SHAPES['fPPPPPPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', __f_20() if _20 is __factory else _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
SHAPES['fPPPPPPPPPPPPPPPPPPPPFPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', __f_23() if _23 is __factory else _23)
SHAPES['fPPPPPPPPPPPPPPPPPPPPPPPF'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
SHAPES['fPPPPPPPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
SHAPES['fKKKKKKKKKKKKKKKKKKKKKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
SHAPES['fPPPPPPPPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24):
    self._0 = _0
    self._1 = _1
    self._2 = _2
    self._3 = _3
    self._4 = _4
    self._5 = _5
    self._6 = _6
    self._7 = _7
    self._8 = _8
    self._9 = _9
    self._10 = _10
    self._11 = _11
    self._12 = _12
    self._13 = _13
    self._14 = _14
    self._15 = _15
    self._16 = _16
    self._17 = _17
    self._18 = _18
    self._19 = _19
    self._20 = _20
    self._21 = _21
    self._22 = _22
    self._23 = _23
    self._24 = __f_24() if _24 is __factory else _24
SHAPES['mPPPPPPPPPPPPPPPPPPPPPPPPF'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24, _25, _26):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
    __set(self, '_25', _25)
    __set(self, '_26', _26)
SHAPES['fPPPPPPPPPPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24, _25, _26, _27):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
    __set(self, '_25', _25)
    __set(self, '_26', _26)
    __set(self, '_27', _27)
SHAPES['fKKKKKKKKKKKKKKKKKKKKKKKKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24, _25, _26, _27):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
    __set(self, '_25', _25)
    __set(self, '_26', _26)
    __set(self, '_27', _27)
SHAPES['fPPPPPPPPPPPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24, _25, _26, _27, _28):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
    __set(self, '_25', _25)
    __set(self, '_26', _26)
    __set(self, '_27', _27)
    __set(self, '_28', _28)
SHAPES['fKKKKKKKKKKKKKKKKKKKKKKKKKKKKK'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24, _25, _26, _27, _28, _29, _30, _31):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
    __set(self, '_25', _25)
    __set(self, '_26', _26)
    __set(self, '_27', _27)
    __set(self, '_28', _28)
    __set(self, '_29', _29)
    __set(self, '_30', _30)
    __set(self, '_31', _31)
SHAPES['fKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKK'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24, _25, _26, _27, _28, _29, _30, _31, _32):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
    __set(self, '_25', _25)
    __set(self, '_26', _26)
    __set(self, '_27', _27)
    __set(self, '_28', _28)
    __set(self, '_29', _29)
    __set(self, '_30', _30)
    __set(self, '_31', _31)
    __set(self, '_32', __f_32() if _32 is __factory else _32)
SHAPES['fPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPF'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24, _25, _26, _27, _28, _29, _30, _31, _32, _33, _34):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
    __set(self, '_25', _25)
    __set(self, '_26', _26)
    __set(self, '_27', _27)
    __set(self, '_28', _28)
    __set(self, '_29', _29)
    __set(self, '_30', _30)
    __set(self, '_31', _31)
    __set(self, '_32', _32)
    __set(self, '_33', _33)
    __set(self, '_34', _34)
SHAPES['fPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24, _25, _26, _27, _28, _29, _30, _31, _32, _33, _34, _35, _36, _37, _38, _39):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
    __set(self, '_25', _25)
    __set(self, '_26', _26)
    __set(self, '_27', _27)
    __set(self, '_28', _28)
    __set(self, '_29', _29)
    __set(self, '_30', _30)
    __set(self, '_31', _31)
    __set(self, '_32', _32)
    __set(self, '_33', _33)
    __set(self, '_34', _34)
    __set(self, '_35', _35)
    __set(self, '_36', _36)
    __set(self, '_37', _37)
    __set(self, '_38', _38)
    __set(self, '_39', _39)
SHAPES['fPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPPP'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24, _25, _26, _27, _28, _29, _30, _31, _32, _33, _34, _35, _36, _37, _38, _39, _40, _41, _42, _43, _44, _45, _46, _47, _48, _49, _50):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
    __set(self, '_25', _25)
    __set(self, '_26', _26)
    __set(self, '_27', _27)
    __set(self, '_28', _28)
    __set(self, '_29', _29)
    __set(self, '_30', _30)
    __set(self, '_31', _31)
    __set(self, '_32', _32)
    __set(self, '_33', _33)
    __set(self, '_34', _34)
    __set(self, '_35', _35)
    __set(self, '_36', _36)
    __set(self, '_37', _37)
    __set(self, '_38', _38)
    __set(self, '_39', _39)
    __set(self, '_40', _40)
    __set(self, '_41', _41)
    __set(self, '_42', _42)
    __set(self, '_43', _43)
    __set(self, '_44', _44)
    __set(self, '_45', _45)
    __set(self, '_46', _46)
    __set(self, '_47', _47)
    __set(self, '_48', _48)
    __set(self, '_49', _49)
    __set(self, '_50', _50)
SHAPES['fKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKK'] = __init__.__code__

def __init__(self, *, _0, _1, _2, _3, _4, _5, _6, _7, _8, _9, _10, _11, _12, _13, _14, _15, _16, _17, _18, _19, _20, _21, _22, _23, _24, _25, _26, _27, _28, _29, _30, _31, _32, _33, _34, _35, _36, _37, _38, _39, _40, _41, _42, _43, _44, _45, _46, _47, _48, _49, _50, _51, _52, _53, _54):
    __set(self, '_0', _0)
    __set(self, '_1', _1)
    __set(self, '_2', _2)
    __set(self, '_3', _3)
    __set(self, '_4', _4)
    __set(self, '_5', _5)
    __set(self, '_6', _6)
    __set(self, '_7', _7)
    __set(self, '_8', _8)
    __set(self, '_9', _9)
    __set(self, '_10', _10)
    __set(self, '_11', _11)
    __set(self, '_12', _12)
    __set(self, '_13', _13)
    __set(self, '_14', _14)
    __set(self, '_15', _15)
    __set(self, '_16', _16)
    __set(self, '_17', _17)
    __set(self, '_18', _18)
    __set(self, '_19', _19)
    __set(self, '_20', _20)
    __set(self, '_21', _21)
    __set(self, '_22', _22)
    __set(self, '_23', _23)
    __set(self, '_24', _24)
    __set(self, '_25', _25)
    __set(self, '_26', _26)
    __set(self, '_27', _27)
    __set(self, '_28', _28)
    __set(self, '_29', _29)
    __set(self, '_30', _30)
    __set(self, '_31', _31)
    __set(self, '_32', _32)
    __set(self, '_33', _33)
    __set(self, '_34', _34)
    __set(self, '_35', _35)
    __set(self, '_36', _36)
    __set(self, '_37', _37)
    __set(self, '_38', _38)
    __set(self, '_39', _39)
    __set(self, '_40', _40)
    __set(self, '_41', _41)
    __set(self, '_42', _42)
    __set(self, '_43', _43)
    __set(self, '_44', _44)
    __set(self, '_45', _45)
    __set(self, '_46', _46)
    __set(self, '_47', _47)
    __set(self, '_48', _48)
    __set(self, '_49', _49)
    __set(self, '_50', _50)
    __set(self, '_51', _51)
    __set(self, '_52', _52)
    __set(self, '_53', _53)
    __set(self, '_54', _54)
SHAPES['fKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKKK'] = __init__.__code__

del __init__
