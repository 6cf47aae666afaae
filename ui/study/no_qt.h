#pragma once
// The study layer must stay testable without a display: if the study library itself is
// ever compiled with Qt's target definitions (someone linked Qt into it), the build fails
// here instead of in review. Widgets including study headers are of course fine.
#if defined(VOXRAY_STUDY_BUILD) && \
    (defined(QT_CORE_LIB) || defined(QT_GUI_LIB) || defined(QT_WIDGETS_LIB))
#error "voxray_study must not depend on Qt"
#endif
