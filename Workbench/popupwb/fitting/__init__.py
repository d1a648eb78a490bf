"""Shape from a 3D model (issue 12): the workbench's side of popupcore.fit_design.

One concept per module: model_source (a ModelMesh from a file, a FreeCAD mesh or shape, and the
source model placed on the card), design_from_fit (a FitResult as a PopUpCard with mechanism
features), fit_report (report.json), preview (preview.png) and fit_run (the stages in order, timed,
shared by `popup fit` and the PopUp_FromModel command).
"""
