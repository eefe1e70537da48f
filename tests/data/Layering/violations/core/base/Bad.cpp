// planted: Qt, a widgets header by its bare name, a layer above base
#include <QtCore/QString>
#include "OutlinerView.h"
#include "model/GuideDocument.h"
#include "base/Math.h"
