"""The note as PDF through Typst (the ``typst`` PyPI package bundles the compiler): figures stay
vector (the sheets' SVG), the ГОСТ frame and main inscription are drawn exactly (layout.py)."""

from __future__ import annotations

from importlib import resources

from ..errors import DrawingError
from ..i18n import Text, message
from .layout import PAGE_H, PAGE_W, PAGES, Page
from .model import Equation, Figure, Heading, Note, Paragraph, Steps, Table

_FONT = {"zh": '("Noto Sans CJK SC",)', "ru": '("Libertinus Serif", "Noto Sans CJK SC")',
         "vi": '("Libertinus Serif", "Noto Sans CJK SC")',
         "en": '("Libertinus Serif", "Noto Sans CJK SC")'}


def s(text: str) -> str:
    """A Typst string literal holding ``text`` as it is (no markup is read in it)."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def _frame(note: Note, page: Page) -> str:
    """The ГОСТ frame and the main inscription (form 2 on the first framed page, 2a after)."""
    m = note.meta
    w = PAGE_W - page.frame_left - page.frame_other
    h = PAGE_H - 2 * page.frame_other
    heads = ", ".join(f"[#{s(t)}]" for t in (m.labels["changed"], m.labels["sheet"], "№",
                                             m.labels["signature"], m.labels["date"]))
    code = s(m.code or m.title)

    def stamp(height: float) -> str:
        return (f"place(bottom + left, dx: {page.frame_left}mm, dy: -{page.frame_other}mm, "
                f"block(width: {w}mm, height: {height}mm, text(size: 7pt, table("
                f"columns: (7mm, 10mm, 23mm, 15mm, 10mm, 1fr, 10mm), rows: (1fr, 1fr, 5mm), "
                f"stroke: 0.5pt, inset: 0.5pt, "
                f"align: center + horizon, [], [], [], [], [], table.cell(rowspan: 3, "
                f"text(size: 10pt)[#{code}]), [#{s(m.labels['sheet'])}], [], [], [], [], [], "
                f"table.cell(rowspan: 2)[#context counter(page).display()], {heads}))))")

    def form2() -> str:
        """ГОСТ 2.104 form 2: 8 rows of 5 mm; the designation, the document's name, Лит.,
        Лист, Листов and the organisation."""
        lab = m.labels
        people = ((lab["developed"], m.student), (lab["checked"], m.instructor), ("", ""),
                  ("", ""), ("", ""))
        cells = ["[]", "[]", "[]", "[]", "[]",
                 f"table.cell(colspan: 6, rowspan: 3, text(size: 10pt)[#{code}])",
                 "[]", "[]", "[]", "[]", "[]", *heads_cells]
        name = s(f"{m.title}\n{lab['note']}")
        org = s("\n".join(x for x in (m.school, m.group) if x))
        for i, (role, person) in enumerate(people):
            cells += [f"table.cell(colspan: 2, align: left)[#{s(role)}]",
                      f"table.cell(align: left)[#{s(person)}]", "[]", "[]"]
            if i == 0:
                cells += [f"table.cell(rowspan: 5, text(size: 9pt)[#{name}])",
                          f"table.cell(colspan: 3)[#{s(lab['letter'])}]",
                          f"[#{s(lab['sheet'])}]", f"[#{s(lab['sheets'])}]"]
            elif i == 1:
                cells += ["[]", "[]", "[]", "[#context counter(page).display()]",
                          "[#context counter(page).final().first()]"]
            elif i == 2:
                cells += [f"table.cell(colspan: 5, rowspan: 3)[#{org}]"]
        return (f"place(bottom + left, dx: {page.frame_left}mm, dy: -{page.frame_other}mm, "
                f"block(width: {w}mm, height: {page.first_stamp_height}mm, text(size: 7pt, "
                f"table(columns: (7mm, 10mm, 23mm, 15mm, 10mm, 70mm, 5mm, 5mm, 5mm, 15mm, "
                f"20mm), rows: 5mm, stroke: 0.5pt, inset: 0.5pt, align: center + horizon, "
                f"{', '.join(cells)}))))")

    heads_cells = [f"[#{s(t)}]" for t in (m.labels["changed"], m.labels["sheet"], "№",
                                          m.labels["signature"], m.labels["date"])]
    return (f"#set page(background: context {{ place(top + left, dx: {page.frame_left}mm, "
            f"dy: {page.frame_other}mm, rect(width: {w}mm, height: {h}mm, stroke: 0.7pt)); "
            f"if counter(page).get().first() == 2 {{ {form2()} }} "
            f"else {{ {stamp(page.stamp_height)} }} }})\n")


def source(note: Note, figures: dict[str, str]) -> str:
    """The Typst source of a note; ``figures`` receives the SVG texts it names (its inputs)."""
    m, lang = note.meta, note.meta.language
    page = PAGES[m.tradition]
    bottom = page.bottom
    out = [f'#set document(title: {s(m.title)}, author: {s(m.student or "-")})',
           (f"#set page(width: {PAGE_W}mm, height: {PAGE_H}mm, margin: (left: {page.left}mm, "
           f"right: {page.right}mm, top: {page.top}mm, bottom: {bottom}mm))"),
           (f'#set text(font: {_FONT[lang]}, size: {page.font_pt}pt, lang: "{lang}", '
           'overhang: false)'),
           f"#set par(leading: {0.65 * page.line_spacing:.2f}em, justify: true)",
           '#set heading(numbering: "1.1")',
           "#show figure.where(kind: table): set figure.caption(position: top)"]
    # title page
    out.append("#align(center)[")
    out.append(f"#text(size: 14pt)[#{s(m.school)}] #v(60mm)")
    out.append(f"#text(size: 18pt, weight: \"bold\")[#{s(m.labels['note'].upper())}] #v(6mm)")
    out.append(f"#text(size: 16pt, weight: \"bold\")[#{s(m.title)}]]")
    out.append("#v(40mm)#align(right)[")
    for key in ("variant", "student", "group", "instructor"):
        value = getattr(m, key)
        if value:
            out.append(f"#{s(m.labels[key] + ': ' + value)} \\")
    out.append("]")
    out.append(f"#align(center + bottom)[#{s(m.year)}]")
    out.append("#pagebreak()")
    if page.frame:
        out.append(_frame(note, page))
    else:
        out.append('#set page(numbering: "1")')
    if page.running_head:
        out.append(f"#set page(header: [#{s(m.title)} #line(length: 100%, stroke: 0.5pt)])")
    out.append(f"#outline(title: {s(m.labels['contents'])})")
    out.append("#pagebreak()")
    eq_n = tab_n = fig_n = 0
    for i, b in enumerate(note.blocks):
        if isinstance(b, Heading):
            out.append(f"#heading(level: {b.level})[#{s(b.text)}]")
        elif isinstance(b, Paragraph):
            out.append(f"#par[#{s(b.text)}]")
        elif isinstance(b, Steps):
            out.append("#enum(" + ", ".join(f"[#{s(x)}]" for x in b.items) + ")")
        elif isinstance(b, Equation):
            eq_n += 1
            out.append(f"#grid(columns: (1fr, auto), inset: (y: 3pt), [#{s(b.line())}], "
                       f"[#{s(f'({eq_n})')}])")
        elif isinstance(b, Table):
            tab_n += 1
            cells = ", ".join(f"[*#{s(x)}*]" for x in b.header)
            body = ", ".join(f"[#{s(x)}]" for row in b.rows for x in row)
            out.append(f"#figure(kind: table, numbering: none, caption: "
                       f"[#{s(message('note.table_caption', lang, n=tab_n, text=b.caption))}], "
                       f"table(columns: {len(b.header)}, inset: 3pt, "
                       f"align: center + horizon, {cells}, {body}))")
        elif isinstance(b, Figure):
            fig_n += 1
            name = f"figure{i}"
            figures[name] = b.svg.decode("utf-8")
            out.append(f"#figure(image(bytes(sys.inputs.at({s(name)})), format: \"svg\", "
                       f"width: 100%), numbering: none, caption: "
                       f"[#{s(message('note.figure_caption', lang, n=fig_n, text=b.caption))}])")
    return "\n".join(out) + "\n"


def to_pdf(note: Note) -> bytes:
    """Compile the note to PDF in memory (no file is written: the figures' SVG reach Typst as
    ``sys.inputs``) with the fonts mechplan bundles and Typst's own, the same on every machine."""
    import typst

    figures: dict[str, str] = {}
    text = source(note, figures)
    fonts = str(resources.files("mechplan") / "fonts")
    try:
        return bytes(typst.compile(text.encode("utf-8"), sys_inputs=figures,  # type: ignore[misc]
                                   font_paths=[fonts], ignore_system_fonts=True))
    except RuntimeError as exc:
        raise DrawingError(Text("errmsg3.typst.cannot_typeset", {"reason": str(exc)})) from None
