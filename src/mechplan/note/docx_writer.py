"""The note as DOCX (python-docx): real heading styles, a TOC field, numbered equations, captioned
tables and figures, page numbers and the tradition's page (layout.py)."""

from __future__ import annotations

import io

from docx import Document
from docx.enum.section import WD_SECTION
from docx.enum.table import WD_ROW_HEIGHT_RULE, WD_TABLE_ALIGNMENT
from docx.enum.text import WD_ALIGN_PARAGRAPH, WD_BREAK, WD_TAB_ALIGNMENT
from docx.oxml import OxmlElement
from docx.oxml.ns import qn
from docx.shared import Mm, Pt, RGBColor

from ..i18n import message
from .layout import PAGE_H, PAGE_W, PAGES, Page
from .model import Equation, Figure, Heading, Note, Paragraph, Steps, Table

_FONTS = {"zh": ("Times New Roman", "SimSun"), "ru": ("Times New Roman", "Times New Roman"),
          "vi": ("Times New Roman", "Times New Roman"), "en": ("Calibri", "Calibri")}


def _field(paragraph, instruction: str, shown: str = "1") -> None:
    """A complex field (PAGE, TOC …) that Word and LibreOffice update."""
    def el(tag: str, **attrs: str):
        e = OxmlElement(tag)
        for k, v in attrs.items():
            e.set(qn(k), v)
        return e

    run = paragraph.add_run()
    run._r.append(el("w:fldChar", **{"w:fldCharType": "begin", "w:dirty": "true"}))
    instr = el("w:instrText", **{"xml:space": "preserve"})
    instr.text = f" {instruction} "
    run._r.append(instr)
    run._r.append(el("w:fldChar", **{"w:fldCharType": "separate"}))
    paragraph.add_run(shown)
    end = paragraph.add_run()
    end._r.append(el("w:fldChar", **{"w:fldCharType": "end"}))


def _borders(section, page: Page) -> None:
    """The ГОСТ frame as page borders around the text (layout.py's margins and frame)."""
    sect = section._sectPr
    pg = OxmlElement("w:pgBorders")
    # a border lies at most 31 pt from what it is measured from, so 20 mm from the page edge
    # cannot be set from the page: it is measured from the text (the 30 mm margin less 10 mm)
    pg.set(qn("w:offsetFrom"), "text")
    spaces = {"top": page.top - page.frame_other, "left": page.left - page.frame_left,
              "bottom": 0.0, "right": page.right - page.frame_other}
    for side in ("top", "left", "bottom", "right"):
        b = OxmlElement(f"w:{side}")
        b.set(qn("w:val"), "single")
        b.set(qn("w:sz"), "8")
        b.set(qn("w:space"), str(round(min(31.0, spaces[side] / 25.4 * 72))))
        b.set(qn("w:color"), "000000")
        pg.append(b)
    sect.append(pg)


def _stamp(section, note: Note, page: Page) -> None:
    """The main inscription of a text document, form 2a (185 × 15 mm), in the footer."""
    m = note.meta
    footer = section.footer
    table = footer.add_table(rows=3, cols=7, width=Mm(185))
    table.style = "Table Grid"
    table.autofit = False
    widths = (7, 10, 23, 15, 10, 110, 10)
    for column, w in zip(table.columns, widths, strict=True):
        column.width = Mm(w)
    for row in table.rows:
        row.height = Mm(5)
        row.height_rule = WD_ROW_HEIGHT_RULE.EXACTLY
        for cell, w in zip(row.cells, widths, strict=True):
            cell.width = Mm(w)
    # from the text's left edge back to the frame's left line
    indent = OxmlElement("w:tblInd")
    # (the indent is to the first cell's text: its 0.19 cm margin is added back)
    indent.set(qn("w:w"), str(round(-(page.left - page.frame_left) / 25.4 * 1440) + 108))
    indent.set(qn("w:type"), "dxa")
    table._tbl.tblPr.append(indent)
    heads = (m.labels["changed"], m.labels["sheet"], "№", m.labels["signature"],
             m.labels["date"])
    for cell, text in zip(table.rows[2].cells[:5], heads, strict=True):
        cell.text = text
    big = table.cell(0, 5).merge(table.cell(2, 5))
    big.text = m.code or m.title
    big.paragraphs[0].alignment = WD_ALIGN_PARAGRAPH.CENTER
    table.cell(0, 6).text = m.labels["sheet"]
    num = table.cell(1, 6).merge(table.cell(2, 6)).paragraphs[0]
    num.alignment = WD_ALIGN_PARAGRAPH.CENTER
    _field(num, "PAGE")
    for row in table.rows:
        for cell in row.cells:
            for p in cell.paragraphs:
                p.paragraph_format.space_before = p.paragraph_format.space_after = Pt(0)
                p.paragraph_format.line_spacing = 1.0
                for r in p.runs:
                    r.font.size = Pt(7)


def _page_number(section) -> None:
    p = section.footer.paragraphs[0]
    p.alignment = WD_ALIGN_PARAGRAPH.CENTER
    _field(p, "PAGE")


def _title_page(doc, note: Note) -> None:
    m = note.meta
    for text, size, bold in ((m.school, 14, False), ("", 14, False),
                             (m.labels["note"].upper(), 16, True), (m.title, 16, True)):
        p = doc.add_paragraph()
        p.alignment = WD_ALIGN_PARAGRAPH.CENTER
        r = p.add_run(text)
        r.font.size, r.bold = Pt(size), bold
    doc.add_paragraph()
    for key in ("variant", "student", "group", "instructor"):
        value = getattr(m, key)
        if value:
            p = doc.add_paragraph(f"{m.labels[key]}: {value}")
            p.alignment = WD_ALIGN_PARAGRAPH.RIGHT
    p = doc.add_paragraph(m.year)
    p.alignment = WD_ALIGN_PARAGRAPH.CENTER


def to_docx(note: Note) -> bytes:
    """The note as a DOCX document."""
    lang = note.meta.language
    page = PAGES[note.meta.tradition]
    doc = Document()
    latin, east = _FONTS[lang]
    for name in ("Normal", "Heading 1", "Heading 2", "Heading 3", "Caption"):
        style = doc.styles[name]
        style.font.name = latin
        rpr = style.element.get_or_add_rPr()
        fonts = rpr.find(qn("w:rFonts"))
        if fonts is None:
            fonts = OxmlElement("w:rFonts")
            rpr.append(fonts)
        fonts.set(qn("w:eastAsia"), east)
    for name in ("Heading 1", "Heading 2", "Heading 3", "Caption"):
        doc.styles[name].font.color.rgb = RGBColor(0, 0, 0)
    doc.styles["Normal"].font.size = Pt(page.font_pt)
    doc.styles["Normal"].paragraph_format.line_spacing = page.line_spacing
    section = doc.sections[0]
    section.page_width, section.page_height = Mm(PAGE_W), Mm(PAGE_H)
    section.left_margin, section.right_margin = Mm(page.left), Mm(page.right)
    section.top_margin, section.bottom_margin = Mm(page.top), Mm(page.bottom)
    section.footer_distance = Mm(page.frame_other if page.frame else 10)
    _title_page(doc, note)
    body = doc.add_section(WD_SECTION.NEW_PAGE)
    body.footer.is_linked_to_previous = False
    if page.frame:
        _borders(body, page)
        _stamp(body, note, page)
    else:
        _page_number(body)
    if page.running_head:
        body.header.is_linked_to_previous = False
        body.header.paragraphs[0].text = note.meta.title
    doc.add_heading(note.meta.labels["contents"], 1)
    _field(doc.add_paragraph(), 'TOC \\o "1-3" \\h \\z \\u', "…")
    doc.add_paragraph().add_run().add_break(WD_BREAK.PAGE)
    text_width = Mm(PAGE_W - page.left - page.right)
    eq_n = tab_n = fig_n = 0
    counters = [0, 0, 0]          # the section numbers 1, 1.2, 1.2.3 (as in the PDF)
    for b in note.blocks:
        if isinstance(b, Heading):
            counters[b.level - 1] += 1
            counters[b.level:] = [0] * (len(counters) - b.level)
            number = ".".join(str(c) for c in counters[:b.level])
            doc.add_heading(f"{number} {b.text}", b.level)
        elif isinstance(b, Paragraph):
            doc.add_paragraph(b.text)
        elif isinstance(b, Steps):
            for i, item in enumerate(b.items, 1):
                doc.add_paragraph(f"{i}. {item}")
        elif isinstance(b, Equation):
            eq_n += 1
            p = doc.add_paragraph(style="Normal")
            p.paragraph_format.tab_stops.add_tab_stop(text_width, WD_TAB_ALIGNMENT.RIGHT)
            p.add_run(b.line()).italic = False
            p.add_run(f"\t({eq_n})")
        elif isinstance(b, Table):
            tab_n += 1
            doc.add_paragraph(message("note.table_caption", lang, n=tab_n, text=b.caption),
                              style="Caption")
            t = doc.add_table(rows=1, cols=len(b.header))
            t.style = "Table Grid"
            t.alignment = WD_TABLE_ALIGNMENT.CENTER
            for cell, text in zip(t.rows[0].cells, b.header, strict=True):
                cell.text = text
                for r in cell.paragraphs[0].runs:
                    r.bold = True
            for row in b.rows:
                cells = t.add_row().cells
                for cell, text in zip(cells, row, strict=True):
                    cell.text = text
        elif isinstance(b, Figure):
            fig_n += 1
            ratio = b.height_mm / b.width_mm
            width = min(text_width, int(Mm(220) / ratio))
            doc.add_picture(io.BytesIO(b.png), width=width)
            doc.paragraphs[-1].alignment = WD_ALIGN_PARAGRAPH.CENTER
            cap = doc.add_paragraph(message("note.figure_caption", lang, n=fig_n,
                                            text=b.caption), style="Caption")
            cap.alignment = WD_ALIGN_PARAGRAPH.CENTER
    settings = doc.settings.element
    upd = OxmlElement("w:updateFields")
    upd.set(qn("w:val"), "true")
    settings.append(upd)
    doc.core_properties.title = note.meta.title
    doc.core_properties.author = note.meta.student
    doc.core_properties.language = lang
    buf = io.BytesIO()
    doc.save(buf)
    return buf.getvalue()
