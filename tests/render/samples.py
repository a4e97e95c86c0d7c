"""Sample sheets shared by the renderer tests."""

from __future__ import annotations

from mechplan.sheet import (
    Arc,
    Arrow,
    Circle,
    HAlign,
    Line,
    Polyline,
    Role,
    Sheet,
    Text,
    VAlign,
    make_frame,
)

#: The known line: 100 mm long, horizontal, on the OUTLINE layer.
LINE_START = (60.0, 200.0)
LINE_END = (160.0, 200.0)

TEXTS = {
    "vi": "Họa đồ vận tốc, tỉ lệ xích μv = 0,1 (m/s)/mm",
    "ru": "План скоростей, полюс p",
    "zh": "速度多边形 极点 p",
    "el": "π ω μ",
}

FIELDS = {
    "vi": {"title": "Phân tích động học cơ cấu culít", "author": "Nguyễn Văn An",
               "group": "CK-K65", "instructor": "TS. Trần Bình",
               "school": "Trường Đại học Bách khoa Hà Nội", "department": "Khoa Cơ khí",
               "date": "12.05.2025", "scale": "1:2", "sheet_number": 1,
               "sheets_total": 3, "designation": "NLM-01"},
    "ru": {"title": "Кинематический анализ кулисного механизма", "author": "Иванов И.И.",
               "group": "РК3-41", "instructor": "Петров П.П.", "school": "МГТУ им. Н.Э. Баумана",
               "date": "12.05.25", "scale": "1:2", "sheet_number": 1, "sheets_total": 3,
               "designation": "ТММ.КП.01.000"},
    "zh": {"title": "牛头刨床机构运动分析", "author": "张伟", "group": "机械21",
               "instructor": "李教授", "school": "清华大学", "department": "机械工程系",
               "date": "2025-05-12", "scale": "1:2", "sheet_number": 1, "sheets_total": 3,
               "designation": "JX-01"},
    "en": {"title": "Kinematic analysis of a shaper", "author": "J. Smith", "group": "ME-2",
               "instructor": "Prof. A. Brown", "school": "University of Manchester",
               "date": "2025-05-12", "scale": "1:2", "sheet_number": 1, "sheets_total": 3,
               "designation": "TM-01"},
}


def content() -> list:
    """Return the drawing content placed on every sample sheet (fits on A4 portrait)."""
    return [
        Line(LINE_START, LINE_END, Role.OUTLINE),
        Line((60.0, 190.0), (160.0, 175.0), Role.DASHED),
        Line((60.0, 180.0), (160.0, 165.0), Role.CHAIN),
        Polyline(((40.0, 100.0), (60.0, 120.0), (80.0, 100.0)), Role.THIN),
        Polyline(((150.0, 100.0), (160.0, 100.0), (155.0, 110.0)), Role.FILL, closed=True,
                 filled=True),
        Circle((100.0, 110.0), 10.0, Role.THIN),
        Arc((130.0, 110.0), 10.0, 0.0, 90.0, Role.CHAIN),
        Arrow((60.0, 150.0), (120.0, 150.0), Role.OUTLINE),
        Arrow((60.0, 150.0), (60.0, 130.0), Role.THIN, 3.0, 1.0),
        Text((40.0, 240.0), TEXTS["vi"], 3.5),
        Text((40.0, 232.0), TEXTS["ru"], 3.5),
        Text((40.0, 224.0), TEXTS["zh"], 3.5),
        Text((150.0, 224.0), TEXTS["el"], 5.0, halign=HAlign.CENTER, valign=VAlign.MIDDLE),
        Text((30.0, 120.0), "b", 3.5, rotation_deg=90.0),
    ]


def sample_sheet(standard: str = "iso", language: str = "vi", size: str = "A4") -> Sheet:
    """Return a framed sample sheet."""
    fields = FIELDS[language] if not (standard == "gost" and language != "ru") else FIELDS["ru"]
    layout = make_frame(size, standard, fields, language=language)
    return layout.sheet(content(), name=f"{standard}_{language}")

