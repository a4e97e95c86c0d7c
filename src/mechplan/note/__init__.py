"""The explanatory note of a course project (пояснительная записка, thuyết minh, 说明书, report).

``model``: the note's content independent of the writer; ``linkage``/``chapters``: the chapters
read off the studies' constructions and JSON; ``docx_writer``/``typst_writer``: DOCX and PDF;
``project``: the project file naming the studies and ``run_project`` writing sheets and note.
A presenter like ``sheet/``: it computes no mechanics of its own.
"""
