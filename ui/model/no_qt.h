#pragma once
// The model layer must stay testable without a display: if the model library itself is
// ever compiled with Qt's target definitions (someone linked Qt into it), the build fails
// here instead of in review. Widgets including model headers are of course fine.
#if defined(VOXRAY_UI_MODEL_BUILD) && \
    (defined(QT_CORE_LIB) || defined(QT_GUI_LIB) || defined(QT_WIDGETS_LIB))
#error "voxray_ui_model must not depend on Qt"
#endif
