"""Shape from a 3D model: the workbench's side of popupcore.fit_design.

One concept per module (where the model comes from is model/model_source.py, below the features:
the cutting sheet reads it too): design_from_fit (a FitResult as a PopUpCard with mechanism
features), fit_report (report.json), preview (preview.png) and fit_run (the stages in order, timed,
shared by `popup fit` and the PopUp_FromModel command).
"""
