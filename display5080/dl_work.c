/* dl_work — the drawing budget (see dl_work.h). */
#include "display5080/dl_work.h"

void dl_work_init(dl_work *w, unsigned long long limit)
{
    w->used = 0;
    w->limit = limit ? limit : DL_WORK_LIMIT;
    w->over = 0;
}

int dl_work_charge(dl_work *w, unsigned long long n)
{
    if (w->over || n > w->limit - w->used) {
        w->over = 1;
        return 0;
    }
    w->used += n;
    return 1;
}
