module top$pipeline$abc(clock,host_write,host_address,host_data,ray_last,line_last,sample$0,sample$1,sample$2,sample$3,dx_neg,dx_mag,dy_neg,dy_mag,centre$0,centre$1,centre$2,centre$3,gx$0,gx$1,gx$2,gx$3,gy$0,gy$1,gy$2,gy$3,gz$0,gz$1,gz$2,gz$3);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [15:0] ray_last;
    input wire  [15:0] line_last;
    input wire  [31:0] sample$0;
    input wire  [31:0] sample$1;
    input wire  [31:0] sample$2;
    input wire  [31:0] sample$3;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    output reg  [31:0] centre$0;
    output reg  [31:0] centre$1;
    output reg  [31:0] centre$2;
    output reg  [31:0] centre$3;
    output reg  [31:0] gx$0;
    output reg  [31:0] gx$1;
    output reg  [31:0] gx$2;
    output reg  [31:0] gx$3;
    output reg  [31:0] gy$0;
    output reg  [31:0] gy$1;
    output reg  [31:0] gy$2;
    output reg  [31:0] gy$3;
    output reg  [31:0] gz$0;
    output reg  [31:0] gz$1;
    output reg  [31:0] gz$2;
    output reg  [31:0] gz$3;
    
    // Constant declarations
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  lanes$0$clock;
    reg  [15:0] lanes$0$ray_last;
    reg  [15:0] lanes$0$line_last;
    reg  [31:0] lanes$0$sample;
    wire  [31:0] lanes$0$t000;
    wire  [31:0] lanes$0$t001;
    wire  [31:0] lanes$0$t002;
    wire  [31:0] lanes$0$t010;
    wire  [31:0] lanes$0$t011;
    wire  [31:0] lanes$0$t012;
    wire  [31:0] lanes$0$t020;
    wire  [31:0] lanes$0$t021;
    wire  [31:0] lanes$0$t022;
    wire  [31:0] lanes$0$t100;
    wire  [31:0] lanes$0$t101;
    wire  [31:0] lanes$0$t102;
    wire  [31:0] lanes$0$t110;
    wire  [31:0] lanes$0$t111;
    wire  [31:0] lanes$0$t112;
    wire  [31:0] lanes$0$t120;
    wire  [31:0] lanes$0$t121;
    wire  [31:0] lanes$0$t122;
    wire  [31:0] lanes$0$t200;
    wire  [31:0] lanes$0$t201;
    wire  [31:0] lanes$0$t202;
    wire  [31:0] lanes$0$t210;
    wire  [31:0] lanes$0$t211;
    wire  [31:0] lanes$0$t212;
    wire  [31:0] lanes$0$t220;
    wire  [31:0] lanes$0$t221;
    wire  [31:0] lanes$0$t222;
    reg  lanes$1$clock;
    reg  [15:0] lanes$1$ray_last;
    reg  [15:0] lanes$1$line_last;
    reg  [31:0] lanes$1$sample;
    wire  [31:0] lanes$1$t000;
    wire  [31:0] lanes$1$t001;
    wire  [31:0] lanes$1$t002;
    wire  [31:0] lanes$1$t010;
    wire  [31:0] lanes$1$t011;
    wire  [31:0] lanes$1$t012;
    wire  [31:0] lanes$1$t020;
    wire  [31:0] lanes$1$t021;
    wire  [31:0] lanes$1$t022;
    wire  [31:0] lanes$1$t100;
    wire  [31:0] lanes$1$t101;
    wire  [31:0] lanes$1$t102;
    wire  [31:0] lanes$1$t110;
    wire  [31:0] lanes$1$t111;
    wire  [31:0] lanes$1$t112;
    wire  [31:0] lanes$1$t120;
    wire  [31:0] lanes$1$t121;
    wire  [31:0] lanes$1$t122;
    wire  [31:0] lanes$1$t200;
    wire  [31:0] lanes$1$t201;
    wire  [31:0] lanes$1$t202;
    wire  [31:0] lanes$1$t210;
    wire  [31:0] lanes$1$t211;
    wire  [31:0] lanes$1$t212;
    wire  [31:0] lanes$1$t220;
    wire  [31:0] lanes$1$t221;
    wire  [31:0] lanes$1$t222;
    reg  lanes$2$clock;
    reg  [15:0] lanes$2$ray_last;
    reg  [15:0] lanes$2$line_last;
    reg  [31:0] lanes$2$sample;
    wire  [31:0] lanes$2$t000;
    wire  [31:0] lanes$2$t001;
    wire  [31:0] lanes$2$t002;
    wire  [31:0] lanes$2$t010;
    wire  [31:0] lanes$2$t011;
    wire  [31:0] lanes$2$t012;
    wire  [31:0] lanes$2$t020;
    wire  [31:0] lanes$2$t021;
    wire  [31:0] lanes$2$t022;
    wire  [31:0] lanes$2$t100;
    wire  [31:0] lanes$2$t101;
    wire  [31:0] lanes$2$t102;
    wire  [31:0] lanes$2$t110;
    wire  [31:0] lanes$2$t111;
    wire  [31:0] lanes$2$t112;
    wire  [31:0] lanes$2$t120;
    wire  [31:0] lanes$2$t121;
    wire  [31:0] lanes$2$t122;
    wire  [31:0] lanes$2$t200;
    wire  [31:0] lanes$2$t201;
    wire  [31:0] lanes$2$t202;
    wire  [31:0] lanes$2$t210;
    wire  [31:0] lanes$2$t211;
    wire  [31:0] lanes$2$t212;
    wire  [31:0] lanes$2$t220;
    wire  [31:0] lanes$2$t221;
    wire  [31:0] lanes$2$t222;
    reg  lanes$3$clock;
    reg  [15:0] lanes$3$ray_last;
    reg  [15:0] lanes$3$line_last;
    reg  [31:0] lanes$3$sample;
    wire  [31:0] lanes$3$t000;
    wire  [31:0] lanes$3$t001;
    wire  [31:0] lanes$3$t002;
    wire  [31:0] lanes$3$t010;
    wire  [31:0] lanes$3$t011;
    wire  [31:0] lanes$3$t012;
    wire  [31:0] lanes$3$t020;
    wire  [31:0] lanes$3$t021;
    wire  [31:0] lanes$3$t022;
    wire  [31:0] lanes$3$t100;
    wire  [31:0] lanes$3$t101;
    wire  [31:0] lanes$3$t102;
    wire  [31:0] lanes$3$t110;
    wire  [31:0] lanes$3$t111;
    wire  [31:0] lanes$3$t112;
    wire  [31:0] lanes$3$t120;
    wire  [31:0] lanes$3$t121;
    wire  [31:0] lanes$3$t122;
    wire  [31:0] lanes$3$t200;
    wire  [31:0] lanes$3$t201;
    wire  [31:0] lanes$3$t202;
    wire  [31:0] lanes$3$t210;
    wire  [31:0] lanes$3$t211;
    wire  [31:0] lanes$3$t212;
    wire  [31:0] lanes$3$t220;
    wire  [31:0] lanes$3$t221;
    wire  [31:0] lanes$3$t222;
    reg  estimators$0$clock;
    reg  [31:0] estimators$0$xp;
    reg  [31:0] estimators$0$xm;
    reg  [31:0] estimators$0$yp;
    reg  [31:0] estimators$0$ym;
    reg  [31:0] estimators$0$kp0;
    reg  [31:0] estimators$0$kp1;
    reg  [31:0] estimators$0$kp2;
    reg  [31:0] estimators$0$kp3;
    reg  [31:0] estimators$0$kp4;
    reg  [31:0] estimators$0$kp5;
    reg  [31:0] estimators$0$kp6;
    reg  [31:0] estimators$0$kp7;
    reg  [31:0] estimators$0$kp8;
    reg  [31:0] estimators$0$km0;
    reg  [31:0] estimators$0$km1;
    reg  [31:0] estimators$0$km2;
    reg  [31:0] estimators$0$km3;
    reg  [31:0] estimators$0$km4;
    reg  [31:0] estimators$0$km5;
    reg  [31:0] estimators$0$km6;
    reg  [31:0] estimators$0$km7;
    reg  [31:0] estimators$0$km8;
    reg  [31:0] estimators$0$c0;
    reg  [31:0] estimators$0$c2;
    reg  [31:0] estimators$0$c6;
    reg  [31:0] estimators$0$c8;
    reg  [63:0] estimators$0$weights10;
    reg  [63:0] estimators$0$basis10_x;
    reg  [63:0] estimators$0$basis10_y;
    reg  [63:0] estimators$0$basis10_z;
    reg  estimators$0$dx_neg;
    reg  [15:0] estimators$0$dx_mag;
    reg  estimators$0$dy_neg;
    reg  [15:0] estimators$0$dy_mag;
    reg  [31:0] estimators$0$centre;
    wire  [31:0] estimators$0$sample;
    wire  [31:0] estimators$0$gx;
    wire  [31:0] estimators$0$gy;
    wire  [31:0] estimators$0$gz;
    reg  estimators$1$clock;
    reg  [31:0] estimators$1$xp;
    reg  [31:0] estimators$1$xm;
    reg  [31:0] estimators$1$yp;
    reg  [31:0] estimators$1$ym;
    reg  [31:0] estimators$1$kp0;
    reg  [31:0] estimators$1$kp1;
    reg  [31:0] estimators$1$kp2;
    reg  [31:0] estimators$1$kp3;
    reg  [31:0] estimators$1$kp4;
    reg  [31:0] estimators$1$kp5;
    reg  [31:0] estimators$1$kp6;
    reg  [31:0] estimators$1$kp7;
    reg  [31:0] estimators$1$kp8;
    reg  [31:0] estimators$1$km0;
    reg  [31:0] estimators$1$km1;
    reg  [31:0] estimators$1$km2;
    reg  [31:0] estimators$1$km3;
    reg  [31:0] estimators$1$km4;
    reg  [31:0] estimators$1$km5;
    reg  [31:0] estimators$1$km6;
    reg  [31:0] estimators$1$km7;
    reg  [31:0] estimators$1$km8;
    reg  [31:0] estimators$1$c0;
    reg  [31:0] estimators$1$c2;
    reg  [31:0] estimators$1$c6;
    reg  [31:0] estimators$1$c8;
    reg  [63:0] estimators$1$weights10;
    reg  [63:0] estimators$1$basis10_x;
    reg  [63:0] estimators$1$basis10_y;
    reg  [63:0] estimators$1$basis10_z;
    reg  estimators$1$dx_neg;
    reg  [15:0] estimators$1$dx_mag;
    reg  estimators$1$dy_neg;
    reg  [15:0] estimators$1$dy_mag;
    reg  [31:0] estimators$1$centre;
    wire  [31:0] estimators$1$sample;
    wire  [31:0] estimators$1$gx;
    wire  [31:0] estimators$1$gy;
    wire  [31:0] estimators$1$gz;
    reg  estimators$2$clock;
    reg  [31:0] estimators$2$xp;
    reg  [31:0] estimators$2$xm;
    reg  [31:0] estimators$2$yp;
    reg  [31:0] estimators$2$ym;
    reg  [31:0] estimators$2$kp0;
    reg  [31:0] estimators$2$kp1;
    reg  [31:0] estimators$2$kp2;
    reg  [31:0] estimators$2$kp3;
    reg  [31:0] estimators$2$kp4;
    reg  [31:0] estimators$2$kp5;
    reg  [31:0] estimators$2$kp6;
    reg  [31:0] estimators$2$kp7;
    reg  [31:0] estimators$2$kp8;
    reg  [31:0] estimators$2$km0;
    reg  [31:0] estimators$2$km1;
    reg  [31:0] estimators$2$km2;
    reg  [31:0] estimators$2$km3;
    reg  [31:0] estimators$2$km4;
    reg  [31:0] estimators$2$km5;
    reg  [31:0] estimators$2$km6;
    reg  [31:0] estimators$2$km7;
    reg  [31:0] estimators$2$km8;
    reg  [31:0] estimators$2$c0;
    reg  [31:0] estimators$2$c2;
    reg  [31:0] estimators$2$c6;
    reg  [31:0] estimators$2$c8;
    reg  [63:0] estimators$2$weights10;
    reg  [63:0] estimators$2$basis10_x;
    reg  [63:0] estimators$2$basis10_y;
    reg  [63:0] estimators$2$basis10_z;
    reg  estimators$2$dx_neg;
    reg  [15:0] estimators$2$dx_mag;
    reg  estimators$2$dy_neg;
    reg  [15:0] estimators$2$dy_mag;
    reg  [31:0] estimators$2$centre;
    wire  [31:0] estimators$2$sample;
    wire  [31:0] estimators$2$gx;
    wire  [31:0] estimators$2$gy;
    wire  [31:0] estimators$2$gz;
    reg  estimators$3$clock;
    reg  [31:0] estimators$3$xp;
    reg  [31:0] estimators$3$xm;
    reg  [31:0] estimators$3$yp;
    reg  [31:0] estimators$3$ym;
    reg  [31:0] estimators$3$kp0;
    reg  [31:0] estimators$3$kp1;
    reg  [31:0] estimators$3$kp2;
    reg  [31:0] estimators$3$kp3;
    reg  [31:0] estimators$3$kp4;
    reg  [31:0] estimators$3$kp5;
    reg  [31:0] estimators$3$kp6;
    reg  [31:0] estimators$3$kp7;
    reg  [31:0] estimators$3$kp8;
    reg  [31:0] estimators$3$km0;
    reg  [31:0] estimators$3$km1;
    reg  [31:0] estimators$3$km2;
    reg  [31:0] estimators$3$km3;
    reg  [31:0] estimators$3$km4;
    reg  [31:0] estimators$3$km5;
    reg  [31:0] estimators$3$km6;
    reg  [31:0] estimators$3$km7;
    reg  [31:0] estimators$3$km8;
    reg  [31:0] estimators$3$c0;
    reg  [31:0] estimators$3$c2;
    reg  [31:0] estimators$3$c6;
    reg  [31:0] estimators$3$c8;
    reg  [63:0] estimators$3$weights10;
    reg  [63:0] estimators$3$basis10_x;
    reg  [63:0] estimators$3$basis10_y;
    reg  [63:0] estimators$3$basis10_z;
    reg  estimators$3$dx_neg;
    reg  [15:0] estimators$3$dx_mag;
    reg  estimators$3$dy_neg;
    reg  [15:0] estimators$3$dy_mag;
    reg  [31:0] estimators$3$centre;
    wire  [31:0] estimators$3$sample;
    wire  [31:0] estimators$3$gx;
    wire  [31:0] estimators$3$gy;
    wire  [31:0] estimators$3$gz;
    reg  regs10$clock;
    reg  regs10$host_write;
    reg  [23:0] regs10$host_address;
    reg  [63:0] regs10$host_data;
    wire  [63:0] regs10$q$0 = 'h0;
    wire  [63:0] regs10$q$1 = 'h0;
    wire  [63:0] regs10$q$2 = 'h0;
    wire  [63:0] regs10$q$3 = 'h0;
    
    // Sub module instances
    top$pipeline$abc$lanes$0 lanes$0(
        .clock(lanes$0$clock),
        .ray_last(lanes$0$ray_last),
        .line_last(lanes$0$line_last),
        .sample(lanes$0$sample),
        .t000(lanes$0$t000),
        .t001(lanes$0$t001),
        .t002(lanes$0$t002),
        .t010(lanes$0$t010),
        .t011(lanes$0$t011),
        .t012(lanes$0$t012),
        .t020(lanes$0$t020),
        .t021(lanes$0$t021),
        .t022(lanes$0$t022),
        .t100(lanes$0$t100),
        .t101(lanes$0$t101),
        .t102(lanes$0$t102),
        .t110(lanes$0$t110),
        .t111(lanes$0$t111),
        .t112(lanes$0$t112),
        .t120(lanes$0$t120),
        .t121(lanes$0$t121),
        .t122(lanes$0$t122),
        .t200(lanes$0$t200),
        .t201(lanes$0$t201),
        .t202(lanes$0$t202),
        .t210(lanes$0$t210),
        .t211(lanes$0$t211),
        .t212(lanes$0$t212),
        .t220(lanes$0$t220),
        .t221(lanes$0$t221),
        .t222(lanes$0$t222)
    );
    top$pipeline$abc$lanes$1 lanes$1(
        .clock(lanes$1$clock),
        .ray_last(lanes$1$ray_last),
        .line_last(lanes$1$line_last),
        .sample(lanes$1$sample),
        .t000(lanes$1$t000),
        .t001(lanes$1$t001),
        .t002(lanes$1$t002),
        .t010(lanes$1$t010),
        .t011(lanes$1$t011),
        .t012(lanes$1$t012),
        .t020(lanes$1$t020),
        .t021(lanes$1$t021),
        .t022(lanes$1$t022),
        .t100(lanes$1$t100),
        .t101(lanes$1$t101),
        .t102(lanes$1$t102),
        .t110(lanes$1$t110),
        .t111(lanes$1$t111),
        .t112(lanes$1$t112),
        .t120(lanes$1$t120),
        .t121(lanes$1$t121),
        .t122(lanes$1$t122),
        .t200(lanes$1$t200),
        .t201(lanes$1$t201),
        .t202(lanes$1$t202),
        .t210(lanes$1$t210),
        .t211(lanes$1$t211),
        .t212(lanes$1$t212),
        .t220(lanes$1$t220),
        .t221(lanes$1$t221),
        .t222(lanes$1$t222)
    );
    top$pipeline$abc$lanes$2 lanes$2(
        .clock(lanes$2$clock),
        .ray_last(lanes$2$ray_last),
        .line_last(lanes$2$line_last),
        .sample(lanes$2$sample),
        .t000(lanes$2$t000),
        .t001(lanes$2$t001),
        .t002(lanes$2$t002),
        .t010(lanes$2$t010),
        .t011(lanes$2$t011),
        .t012(lanes$2$t012),
        .t020(lanes$2$t020),
        .t021(lanes$2$t021),
        .t022(lanes$2$t022),
        .t100(lanes$2$t100),
        .t101(lanes$2$t101),
        .t102(lanes$2$t102),
        .t110(lanes$2$t110),
        .t111(lanes$2$t111),
        .t112(lanes$2$t112),
        .t120(lanes$2$t120),
        .t121(lanes$2$t121),
        .t122(lanes$2$t122),
        .t200(lanes$2$t200),
        .t201(lanes$2$t201),
        .t202(lanes$2$t202),
        .t210(lanes$2$t210),
        .t211(lanes$2$t211),
        .t212(lanes$2$t212),
        .t220(lanes$2$t220),
        .t221(lanes$2$t221),
        .t222(lanes$2$t222)
    );
    top$pipeline$abc$lanes$3 lanes$3(
        .clock(lanes$3$clock),
        .ray_last(lanes$3$ray_last),
        .line_last(lanes$3$line_last),
        .sample(lanes$3$sample),
        .t000(lanes$3$t000),
        .t001(lanes$3$t001),
        .t002(lanes$3$t002),
        .t010(lanes$3$t010),
        .t011(lanes$3$t011),
        .t012(lanes$3$t012),
        .t020(lanes$3$t020),
        .t021(lanes$3$t021),
        .t022(lanes$3$t022),
        .t100(lanes$3$t100),
        .t101(lanes$3$t101),
        .t102(lanes$3$t102),
        .t110(lanes$3$t110),
        .t111(lanes$3$t111),
        .t112(lanes$3$t112),
        .t120(lanes$3$t120),
        .t121(lanes$3$t121),
        .t122(lanes$3$t122),
        .t200(lanes$3$t200),
        .t201(lanes$3$t201),
        .t202(lanes$3$t202),
        .t210(lanes$3$t210),
        .t211(lanes$3$t211),
        .t212(lanes$3$t212),
        .t220(lanes$3$t220),
        .t221(lanes$3$t221),
        .t222(lanes$3$t222)
    );
    top$pipeline$abc$estimators$0 estimators$0(
        .clock(estimators$0$clock),
        .xp(estimators$0$xp),
        .xm(estimators$0$xm),
        .yp(estimators$0$yp),
        .ym(estimators$0$ym),
        .kp0(estimators$0$kp0),
        .kp1(estimators$0$kp1),
        .kp2(estimators$0$kp2),
        .kp3(estimators$0$kp3),
        .kp4(estimators$0$kp4),
        .kp5(estimators$0$kp5),
        .kp6(estimators$0$kp6),
        .kp7(estimators$0$kp7),
        .kp8(estimators$0$kp8),
        .km0(estimators$0$km0),
        .km1(estimators$0$km1),
        .km2(estimators$0$km2),
        .km3(estimators$0$km3),
        .km4(estimators$0$km4),
        .km5(estimators$0$km5),
        .km6(estimators$0$km6),
        .km7(estimators$0$km7),
        .km8(estimators$0$km8),
        .c0(estimators$0$c0),
        .c2(estimators$0$c2),
        .c6(estimators$0$c6),
        .c8(estimators$0$c8),
        .weights10(estimators$0$weights10),
        .basis10_x(estimators$0$basis10_x),
        .basis10_y(estimators$0$basis10_y),
        .basis10_z(estimators$0$basis10_z),
        .dx_neg(estimators$0$dx_neg),
        .dx_mag(estimators$0$dx_mag),
        .dy_neg(estimators$0$dy_neg),
        .dy_mag(estimators$0$dy_mag),
        .centre(estimators$0$centre),
        .sample(estimators$0$sample),
        .gx(estimators$0$gx),
        .gy(estimators$0$gy),
        .gz(estimators$0$gz)
    );
    top$pipeline$abc$estimators$1 estimators$1(
        .clock(estimators$1$clock),
        .xp(estimators$1$xp),
        .xm(estimators$1$xm),
        .yp(estimators$1$yp),
        .ym(estimators$1$ym),
        .kp0(estimators$1$kp0),
        .kp1(estimators$1$kp1),
        .kp2(estimators$1$kp2),
        .kp3(estimators$1$kp3),
        .kp4(estimators$1$kp4),
        .kp5(estimators$1$kp5),
        .kp6(estimators$1$kp6),
        .kp7(estimators$1$kp7),
        .kp8(estimators$1$kp8),
        .km0(estimators$1$km0),
        .km1(estimators$1$km1),
        .km2(estimators$1$km2),
        .km3(estimators$1$km3),
        .km4(estimators$1$km4),
        .km5(estimators$1$km5),
        .km6(estimators$1$km6),
        .km7(estimators$1$km7),
        .km8(estimators$1$km8),
        .c0(estimators$1$c0),
        .c2(estimators$1$c2),
        .c6(estimators$1$c6),
        .c8(estimators$1$c8),
        .weights10(estimators$1$weights10),
        .basis10_x(estimators$1$basis10_x),
        .basis10_y(estimators$1$basis10_y),
        .basis10_z(estimators$1$basis10_z),
        .dx_neg(estimators$1$dx_neg),
        .dx_mag(estimators$1$dx_mag),
        .dy_neg(estimators$1$dy_neg),
        .dy_mag(estimators$1$dy_mag),
        .centre(estimators$1$centre),
        .sample(estimators$1$sample),
        .gx(estimators$1$gx),
        .gy(estimators$1$gy),
        .gz(estimators$1$gz)
    );
    top$pipeline$abc$estimators$2 estimators$2(
        .clock(estimators$2$clock),
        .xp(estimators$2$xp),
        .xm(estimators$2$xm),
        .yp(estimators$2$yp),
        .ym(estimators$2$ym),
        .kp0(estimators$2$kp0),
        .kp1(estimators$2$kp1),
        .kp2(estimators$2$kp2),
        .kp3(estimators$2$kp3),
        .kp4(estimators$2$kp4),
        .kp5(estimators$2$kp5),
        .kp6(estimators$2$kp6),
        .kp7(estimators$2$kp7),
        .kp8(estimators$2$kp8),
        .km0(estimators$2$km0),
        .km1(estimators$2$km1),
        .km2(estimators$2$km2),
        .km3(estimators$2$km3),
        .km4(estimators$2$km4),
        .km5(estimators$2$km5),
        .km6(estimators$2$km6),
        .km7(estimators$2$km7),
        .km8(estimators$2$km8),
        .c0(estimators$2$c0),
        .c2(estimators$2$c2),
        .c6(estimators$2$c6),
        .c8(estimators$2$c8),
        .weights10(estimators$2$weights10),
        .basis10_x(estimators$2$basis10_x),
        .basis10_y(estimators$2$basis10_y),
        .basis10_z(estimators$2$basis10_z),
        .dx_neg(estimators$2$dx_neg),
        .dx_mag(estimators$2$dx_mag),
        .dy_neg(estimators$2$dy_neg),
        .dy_mag(estimators$2$dy_mag),
        .centre(estimators$2$centre),
        .sample(estimators$2$sample),
        .gx(estimators$2$gx),
        .gy(estimators$2$gy),
        .gz(estimators$2$gz)
    );
    top$pipeline$abc$estimators$3 estimators$3(
        .clock(estimators$3$clock),
        .xp(estimators$3$xp),
        .xm(estimators$3$xm),
        .yp(estimators$3$yp),
        .ym(estimators$3$ym),
        .kp0(estimators$3$kp0),
        .kp1(estimators$3$kp1),
        .kp2(estimators$3$kp2),
        .kp3(estimators$3$kp3),
        .kp4(estimators$3$kp4),
        .kp5(estimators$3$kp5),
        .kp6(estimators$3$kp6),
        .kp7(estimators$3$kp7),
        .kp8(estimators$3$kp8),
        .km0(estimators$3$km0),
        .km1(estimators$3$km1),
        .km2(estimators$3$km2),
        .km3(estimators$3$km3),
        .km4(estimators$3$km4),
        .km5(estimators$3$km5),
        .km6(estimators$3$km6),
        .km7(estimators$3$km7),
        .km8(estimators$3$km8),
        .c0(estimators$3$c0),
        .c2(estimators$3$c2),
        .c6(estimators$3$c6),
        .c8(estimators$3$c8),
        .weights10(estimators$3$weights10),
        .basis10_x(estimators$3$basis10_x),
        .basis10_y(estimators$3$basis10_y),
        .basis10_z(estimators$3$basis10_z),
        .dx_neg(estimators$3$dx_neg),
        .dx_mag(estimators$3$dx_mag),
        .dy_neg(estimators$3$dy_neg),
        .dy_mag(estimators$3$dy_mag),
        .centre(estimators$3$centre),
        .sample(estimators$3$sample),
        .gx(estimators$3$gx),
        .gy(estimators$3$gy),
        .gz(estimators$3$gz)
    );
    
    // Update code
    reg  [31:0] centre$0_pass;
    reg  [31:0] centre$1_pass;
    reg  [31:0] centre$2_pass;
    reg  [31:0] centre$3_pass;
    reg  [31:0] gx$0_pass;
    reg  [31:0] gx$1_pass;
    reg  [31:0] gx$2_pass;
    reg  [31:0] gx$3_pass;
    reg  [31:0] gy$0_pass;
    reg  [31:0] gy$1_pass;
    reg  [31:0] gy$2_pass;
    reg  [31:0] gy$3_pass;
    reg  [31:0] gz$0_pass;
    reg  [31:0] gz$1_pass;
    reg  [31:0] gz$2_pass;
    reg  [31:0] gz$3_pass;
    always @(*) begin
        regs10$clock = clock;
        regs10$host_write = host_write;
        regs10$host_address = host_address;
        regs10$host_data = host_data;
        estimators$0$weights10 = regs10$q$0;
        estimators$0$basis10_x = regs10$q$1;
        estimators$0$basis10_y = regs10$q$2;
        estimators$0$basis10_z = regs10$q$3;
        lanes$0$clock = clock;
        lanes$0$ray_last = ray_last;
        lanes$0$line_last = line_last;
        estimators$0$clock = clock;
        lanes$0$sample = sample$0;
        estimators$0$xp = lanes$0$t101;
        estimators$0$xm = lanes$0$t121;
        estimators$0$yp = lanes$0$t011;
        estimators$0$ym = lanes$0$t211;
        estimators$0$c0 = lanes$0$t001;
        estimators$0$c2 = lanes$0$t021;
        estimators$0$c6 = lanes$0$t201;
        estimators$0$c8 = lanes$0$t221;
        estimators$0$dx_neg = dx_neg;
        estimators$0$dx_mag = dx_mag;
        estimators$0$dy_neg = dy_neg;
        estimators$0$dy_mag = dy_mag;
        estimators$0$centre = lanes$0$t111;
        centre$0_pass = 'h0;
        gx$0_pass = 'h0;
        gy$0_pass = 'h0;
        gz$0_pass = 'h0;
        if (enabled) begin
            centre$0_pass = estimators$0$sample;
            gx$0_pass = estimators$0$gx;
            gy$0_pass = estimators$0$gy;
            gz$0_pass = estimators$0$gz;
        end
        estimators$1$weights10 = regs10$q$0;
        estimators$1$basis10_x = regs10$q$1;
        estimators$1$basis10_y = regs10$q$2;
        estimators$1$basis10_z = regs10$q$3;
        lanes$1$clock = clock;
        lanes$1$ray_last = ray_last;
        lanes$1$line_last = line_last;
        estimators$1$clock = clock;
        lanes$1$sample = sample$1;
        estimators$1$xp = lanes$1$t101;
        estimators$1$xm = lanes$1$t121;
        estimators$1$yp = lanes$1$t011;
        estimators$1$ym = lanes$1$t211;
        estimators$1$c0 = lanes$1$t001;
        estimators$1$c2 = lanes$1$t021;
        estimators$1$c6 = lanes$1$t201;
        estimators$1$c8 = lanes$1$t221;
        estimators$1$dx_neg = dx_neg;
        estimators$1$dx_mag = dx_mag;
        estimators$1$dy_neg = dy_neg;
        estimators$1$dy_mag = dy_mag;
        estimators$1$centre = lanes$1$t111;
        centre$1_pass = 'h0;
        gx$1_pass = 'h0;
        gy$1_pass = 'h0;
        gz$1_pass = 'h0;
        if (enabled) begin
            centre$1_pass = estimators$1$sample;
            gx$1_pass = estimators$1$gx;
            gy$1_pass = estimators$1$gy;
            gz$1_pass = estimators$1$gz;
        end
        estimators$2$weights10 = regs10$q$0;
        estimators$2$basis10_x = regs10$q$1;
        estimators$2$basis10_y = regs10$q$2;
        estimators$2$basis10_z = regs10$q$3;
        lanes$2$clock = clock;
        lanes$2$ray_last = ray_last;
        lanes$2$line_last = line_last;
        estimators$2$clock = clock;
        lanes$2$sample = sample$2;
        estimators$2$xp = lanes$2$t101;
        estimators$2$xm = lanes$2$t121;
        estimators$2$yp = lanes$2$t011;
        estimators$2$ym = lanes$2$t211;
        estimators$2$c0 = lanes$2$t001;
        estimators$2$c2 = lanes$2$t021;
        estimators$2$c6 = lanes$2$t201;
        estimators$2$c8 = lanes$2$t221;
        estimators$2$dx_neg = dx_neg;
        estimators$2$dx_mag = dx_mag;
        estimators$2$dy_neg = dy_neg;
        estimators$2$dy_mag = dy_mag;
        estimators$2$centre = lanes$2$t111;
        centre$2_pass = 'h0;
        gx$2_pass = 'h0;
        gy$2_pass = 'h0;
        gz$2_pass = 'h0;
        if (enabled) begin
            centre$2_pass = estimators$2$sample;
            gx$2_pass = estimators$2$gx;
            gy$2_pass = estimators$2$gy;
            gz$2_pass = estimators$2$gz;
        end
        estimators$3$weights10 = regs10$q$0;
        estimators$3$basis10_x = regs10$q$1;
        estimators$3$basis10_y = regs10$q$2;
        estimators$3$basis10_z = regs10$q$3;
        lanes$3$clock = clock;
        lanes$3$ray_last = ray_last;
        lanes$3$line_last = line_last;
        estimators$3$clock = clock;
        lanes$3$sample = sample$3;
        estimators$3$xp = lanes$3$t101;
        estimators$3$xm = lanes$3$t121;
        estimators$3$yp = lanes$3$t011;
        estimators$3$ym = lanes$3$t211;
        estimators$3$c0 = lanes$3$t001;
        estimators$3$c2 = lanes$3$t021;
        estimators$3$c6 = lanes$3$t201;
        estimators$3$c8 = lanes$3$t221;
        estimators$3$dx_neg = dx_neg;
        estimators$3$dx_mag = dx_mag;
        estimators$3$dy_neg = dy_neg;
        estimators$3$dy_mag = dy_mag;
        estimators$3$centre = lanes$3$t111;
        centre$3_pass = 'h0;
        gx$3_pass = 'h0;
        gy$3_pass = 'h0;
        gz$3_pass = 'h0;
        if (enabled) begin
            centre$3_pass = estimators$3$sample;
            gx$3_pass = estimators$3$gx;
            gy$3_pass = estimators$3$gy;
            gz$3_pass = estimators$3$gz;
        end
        estimators$0$kp0 = lanes$1$t001;
        estimators$0$kp1 = lanes$1$t011;
        estimators$0$kp2 = lanes$1$t021;
        estimators$0$kp3 = lanes$1$t101;
        estimators$0$kp4 = lanes$1$t111;
        estimators$0$kp5 = lanes$1$t121;
        estimators$0$kp6 = lanes$1$t201;
        estimators$0$kp7 = lanes$1$t211;
        estimators$0$kp8 = lanes$1$t221;
        estimators$1$kp0 = lanes$2$t001;
        estimators$1$kp1 = lanes$2$t011;
        estimators$1$kp2 = lanes$2$t021;
        estimators$1$kp3 = lanes$2$t101;
        estimators$1$kp4 = lanes$2$t111;
        estimators$1$kp5 = lanes$2$t121;
        estimators$1$kp6 = lanes$2$t201;
        estimators$1$kp7 = lanes$2$t211;
        estimators$1$kp8 = lanes$2$t221;
        estimators$2$kp0 = lanes$3$t001;
        estimators$2$kp1 = lanes$3$t011;
        estimators$2$kp2 = lanes$3$t021;
        estimators$2$kp3 = lanes$3$t101;
        estimators$2$kp4 = lanes$3$t111;
        estimators$2$kp5 = lanes$3$t121;
        estimators$2$kp6 = lanes$3$t201;
        estimators$2$kp7 = lanes$3$t211;
        estimators$2$kp8 = lanes$3$t221;
        estimators$1$km0 = lanes$0$t001;
        estimators$1$km1 = lanes$0$t011;
        estimators$1$km2 = lanes$0$t021;
        estimators$1$km3 = lanes$0$t101;
        estimators$1$km4 = lanes$0$t111;
        estimators$1$km5 = lanes$0$t121;
        estimators$1$km6 = lanes$0$t201;
        estimators$1$km7 = lanes$0$t211;
        estimators$1$km8 = lanes$0$t221;
        estimators$2$km0 = lanes$1$t001;
        estimators$2$km1 = lanes$1$t011;
        estimators$2$km2 = lanes$1$t021;
        estimators$2$km3 = lanes$1$t101;
        estimators$2$km4 = lanes$1$t111;
        estimators$2$km5 = lanes$1$t121;
        estimators$2$km6 = lanes$1$t201;
        estimators$2$km7 = lanes$1$t211;
        estimators$2$km8 = lanes$1$t221;
        estimators$3$km0 = lanes$2$t001;
        estimators$3$km1 = lanes$2$t011;
        estimators$3$km2 = lanes$2$t021;
        estimators$3$km3 = lanes$2$t101;
        estimators$3$km4 = lanes$2$t111;
        estimators$3$km5 = lanes$2$t121;
        estimators$3$km6 = lanes$2$t201;
        estimators$3$km7 = lanes$2$t211;
        estimators$3$km8 = lanes$2$t221;
        estimators$3$kp0 = lanes$0$t000;
        estimators$3$kp1 = lanes$0$t010;
        estimators$3$kp2 = lanes$0$t020;
        estimators$3$kp3 = lanes$0$t100;
        estimators$3$kp4 = lanes$0$t110;
        estimators$3$kp5 = lanes$0$t120;
        estimators$3$kp6 = lanes$0$t200;
        estimators$3$kp7 = lanes$0$t210;
        estimators$3$kp8 = lanes$0$t220;
        estimators$0$km0 = lanes$3$t002;
        estimators$0$km1 = lanes$3$t012;
        estimators$0$km2 = lanes$3$t022;
        estimators$0$km3 = lanes$3$t102;
        estimators$0$km4 = lanes$3$t112;
        estimators$0$km5 = lanes$3$t122;
        estimators$0$km6 = lanes$3$t202;
        estimators$0$km7 = lanes$3$t212;
        estimators$0$km8 = lanes$3$t222;
        centre$0 = centre$0_pass;
        centre$1 = centre$1_pass;
        centre$2 = centre$2_pass;
        centre$3 = centre$3_pass;
        gx$0 = gx$0_pass;
        gx$1 = gx$1_pass;
        gx$2 = gx$2_pass;
        gx$3 = gx$3_pass;
        gy$0 = gy$0_pass;
        gy$1 = gy$1_pass;
        gy$2 = gy$2_pass;
        gy$3 = gy$3_pass;
        gz$0 = gz$0_pass;
        gz$1 = gz$1_pass;
        gz$2 = gz$2_pass;
        gz$3 = gz$3_pass;
    end
    
endmodule // top$pipeline$abc
module top$pipeline$abc$estimators$0(clock,xp,xm,yp,ym,kp0,kp1,kp2,kp3,kp4,kp5,kp6,kp7,kp8,km0,km1,km2,km3,km4,km5,km6,km7,km8,c0,c2,c6,c8,weights10,basis10_x,basis10_y,basis10_z,dx_neg,dx_mag,dy_neg,dy_mag,centre,sample,gx,gy,gz);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] xp;
    input wire  [31:0] xm;
    input wire  [31:0] yp;
    input wire  [31:0] ym;
    input wire  [31:0] kp0;
    input wire  [31:0] kp1;
    input wire  [31:0] kp2;
    input wire  [31:0] kp3;
    input wire  [31:0] kp4;
    input wire  [31:0] kp5;
    input wire  [31:0] kp6;
    input wire  [31:0] kp7;
    input wire  [31:0] kp8;
    input wire  [31:0] km0;
    input wire  [31:0] km1;
    input wire  [31:0] km2;
    input wire  [31:0] km3;
    input wire  [31:0] km4;
    input wire  [31:0] km5;
    input wire  [31:0] km6;
    input wire  [31:0] km7;
    input wire  [31:0] km8;
    input wire  [31:0] c0;
    input wire  [31:0] c2;
    input wire  [31:0] c6;
    input wire  [31:0] c8;
    input wire  [63:0] weights10;
    input wire  [63:0] basis10_x;
    input wire  [63:0] basis10_y;
    input wire  [63:0] basis10_z;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [31:0] centre;
    output reg  [31:0] sample;
    output reg  [31:0] gx;
    output reg  [31:0] gy;
    output reg  [31:0] gz;
    
    // Constant declarations
    localparam  n12 = 1'b1;
    localparam  n26 = 1'b0;
    localparam  n10 = 1'b0;
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  sign_ext = 64'hffffffff00000000;
    
    // Stub signals
    reg  sums26$clock;
    reg  [31:0] sums26$xp;
    reg  [31:0] sums26$xm;
    reg  [31:0] sums26$yp;
    reg  [31:0] sums26$ym;
    reg  [31:0] sums26$c0;
    reg  [31:0] sums26$c2;
    reg  [31:0] sums26$c6;
    reg  [31:0] sums26$c8;
    reg  [31:0] sums26$kp0;
    reg  [31:0] sums26$kp1;
    reg  [31:0] sums26$kp2;
    reg  [31:0] sums26$kp3;
    reg  [31:0] sums26$kp4;
    reg  [31:0] sums26$kp5;
    reg  [31:0] sums26$kp6;
    reg  [31:0] sums26$kp7;
    reg  [31:0] sums26$kp8;
    reg  [31:0] sums26$km0;
    reg  [31:0] sums26$km1;
    reg  [31:0] sums26$km2;
    reg  [31:0] sums26$km3;
    reg  [31:0] sums26$km4;
    reg  [31:0] sums26$km5;
    reg  [31:0] sums26$km6;
    reg  [31:0] sums26$km7;
    reg  [31:0] sums26$km8;
    wire  [31:0] sums26$gx = 'h0;
    wire  [31:0] sums26$gy = 'h0;
    wire  [31:0] sums26$gr = 'h0;
    reg  basis10$clock;
    reg  [31:0] basis10$xp;
    reg  [31:0] basis10$xm;
    reg  [31:0] basis10$yp;
    reg  [31:0] basis10$ym;
    reg  [31:0] basis10$kp1;
    reg  [31:0] basis10$kp3;
    reg  [31:0] basis10$kp4;
    reg  [31:0] basis10$kp5;
    reg  [31:0] basis10$kp7;
    reg  [31:0] basis10$km1;
    reg  [31:0] basis10$km3;
    reg  [31:0] basis10$km4;
    reg  [31:0] basis10$km5;
    reg  [31:0] basis10$km7;
    reg  basis10$dx_neg;
    reg  [15:0] basis10$dx_mag;
    reg  basis10$dy_neg;
    reg  [15:0] basis10$dy_mag;
    reg  [63:0] basis10$weights;
    reg  [63:0] basis10$basis_x;
    reg  [63:0] basis10$basis_y;
    reg  [63:0] basis10$basis_z;
    wire  [63:0] basis10$gx = 'h0;
    wire  [63:0] basis10$gy = 'h0;
    wire  [63:0] basis10$gz = 'h0;
    reg  [63:0] b10x_q$0$d;
    wire  [63:0] b10x_q$0$q;
    reg  b10x_q$0$clock;
    reg  [63:0] b10x_q$1$d;
    wire  [63:0] b10x_q$1$q;
    reg  b10x_q$1$clock;
    reg  [63:0] b10y_q$0$d;
    wire  [63:0] b10y_q$0$q;
    reg  b10y_q$0$clock;
    reg  [63:0] b10y_q$1$d;
    wire  [63:0] b10y_q$1$q;
    reg  b10y_q$1$clock;
    reg  [63:0] b10z_q$0$d;
    wire  [63:0] b10z_q$0$q;
    reg  b10z_q$0$clock;
    reg  [63:0] b10z_q$1$d;
    wire  [63:0] b10z_q$1$q;
    reg  b10z_q$1$clock;
    reg  [31:0] gx_q$0$d;
    wire  [31:0] gx_q$0$q;
    reg  gx_q$0$clock;
    reg  [31:0] gx_q$1$d;
    wire  [31:0] gx_q$1$q;
    reg  gx_q$1$clock;
    reg  [31:0] gx_q$2$d;
    wire  [31:0] gx_q$2$q;
    reg  gx_q$2$clock;
    reg  [31:0] gx_q$3$d;
    wire  [31:0] gx_q$3$q;
    reg  gx_q$3$clock;
    reg  [31:0] gx_q$4$d;
    wire  [31:0] gx_q$4$q;
    reg  gx_q$4$clock;
    reg  [31:0] gx_q$5$d;
    wire  [31:0] gx_q$5$q;
    reg  gx_q$5$clock;
    reg  [31:0] gy_q$0$d;
    wire  [31:0] gy_q$0$q;
    reg  gy_q$0$clock;
    reg  [31:0] gy_q$1$d;
    wire  [31:0] gy_q$1$q;
    reg  gy_q$1$clock;
    reg  [31:0] gy_q$2$d;
    wire  [31:0] gy_q$2$q;
    reg  gy_q$2$clock;
    reg  [31:0] gy_q$3$d;
    wire  [31:0] gy_q$3$q;
    reg  gy_q$3$clock;
    reg  [31:0] gy_q$4$d;
    wire  [31:0] gy_q$4$q;
    reg  gy_q$4$clock;
    reg  [31:0] gy_q$5$d;
    wire  [31:0] gy_q$5$q;
    reg  gy_q$5$clock;
    reg  [31:0] gr_q$0$d;
    wire  [31:0] gr_q$0$q;
    reg  gr_q$0$clock;
    reg  [31:0] gr_q$1$d;
    wire  [31:0] gr_q$1$q;
    reg  gr_q$1$clock;
    reg  [31:0] gr_q$2$d;
    wire  [31:0] gr_q$2$q;
    reg  gr_q$2$clock;
    reg  [31:0] gr_q$3$d;
    wire  [31:0] gr_q$3$q;
    reg  gr_q$3$clock;
    reg  [31:0] gr_q$4$d;
    wire  [31:0] gr_q$4$q;
    reg  gr_q$4$clock;
    reg  [31:0] gr_q$5$d;
    wire  [31:0] gr_q$5$q;
    reg  gr_q$5$clock;
    reg  dx_neg_q$0$d;
    wire  dx_neg_q$0$q;
    reg  dx_neg_q$0$clock;
    reg  dx_neg_q$1$d;
    wire  dx_neg_q$1$q;
    reg  dx_neg_q$1$clock;
    reg  dx_neg_q$2$d;
    wire  dx_neg_q$2$q;
    reg  dx_neg_q$2$clock;
    reg  dx_neg_q$3$d;
    wire  dx_neg_q$3$q;
    reg  dx_neg_q$3$clock;
    reg  dx_neg_q$4$d;
    wire  dx_neg_q$4$q;
    reg  dx_neg_q$4$clock;
    reg  [15:0] dx_mag_q$0$d;
    wire  [15:0] dx_mag_q$0$q;
    reg  dx_mag_q$0$clock;
    reg  [15:0] dx_mag_q$1$d;
    wire  [15:0] dx_mag_q$1$q;
    reg  dx_mag_q$1$clock;
    reg  [15:0] dx_mag_q$2$d;
    wire  [15:0] dx_mag_q$2$q;
    reg  dx_mag_q$2$clock;
    reg  [15:0] dx_mag_q$3$d;
    wire  [15:0] dx_mag_q$3$q;
    reg  dx_mag_q$3$clock;
    reg  [15:0] dx_mag_q$4$d;
    wire  [15:0] dx_mag_q$4$q;
    reg  dx_mag_q$4$clock;
    reg  dy_neg_q$0$d;
    wire  dy_neg_q$0$q;
    reg  dy_neg_q$0$clock;
    reg  dy_neg_q$1$d;
    wire  dy_neg_q$1$q;
    reg  dy_neg_q$1$clock;
    reg  dy_neg_q$2$d;
    wire  dy_neg_q$2$q;
    reg  dy_neg_q$2$clock;
    reg  dy_neg_q$3$d;
    wire  dy_neg_q$3$q;
    reg  dy_neg_q$3$clock;
    reg  dy_neg_q$4$d;
    wire  dy_neg_q$4$q;
    reg  dy_neg_q$4$clock;
    reg  [15:0] dy_mag_q$0$d;
    wire  [15:0] dy_mag_q$0$q;
    reg  dy_mag_q$0$clock;
    reg  [15:0] dy_mag_q$1$d;
    wire  [15:0] dy_mag_q$1$q;
    reg  dy_mag_q$1$clock;
    reg  [15:0] dy_mag_q$2$d;
    wire  [15:0] dy_mag_q$2$q;
    reg  dy_mag_q$2$clock;
    reg  [15:0] dy_mag_q$3$d;
    wire  [15:0] dy_mag_q$3$q;
    reg  dy_mag_q$3$clock;
    reg  [15:0] dy_mag_q$4$d;
    wire  [15:0] dy_mag_q$4$q;
    reg  dy_mag_q$4$clock;
    reg  [31:0] px$g;
    reg  px$d_neg;
    reg  [15:0] px$d_mag;
    wire  [63:0] px$y;
    reg  [31:0] py$g;
    reg  py$d_neg;
    reg  [15:0] py$d_mag;
    wire  [63:0] py$y;
    reg  [63:0] px_q$d;
    wire  [63:0] px_q$q;
    reg  px_q$clock;
    reg  [63:0] py_q$d;
    wire  [63:0] py_q$q;
    reg  py_q$clock;
    reg  front_top$clock;
    reg  [31:0] front_top$a;
    reg  [31:0] front_top$b;
    reg  [15:0] front_top$w;
    wire  [31:0] front_top$y;
    reg  front_bottom$clock;
    reg  [31:0] front_bottom$a;
    reg  [31:0] front_bottom$b;
    reg  [15:0] front_bottom$w;
    wire  [31:0] front_bottom$y;
    reg  front_y$clock;
    reg  [31:0] front_y$a;
    reg  [31:0] front_y$b;
    reg  [15:0] front_y$w;
    wire  [31:0] front_y$y;
    reg  back_top$clock;
    reg  [31:0] back_top$a;
    reg  [31:0] back_top$b;
    reg  [15:0] back_top$w;
    wire  [31:0] back_top$y;
    reg  back_bottom$clock;
    reg  [31:0] back_bottom$a;
    reg  [31:0] back_bottom$b;
    reg  [15:0] back_bottom$w;
    wire  [31:0] back_bottom$y;
    reg  back_y$clock;
    reg  [31:0] back_y$a;
    reg  [31:0] back_y$b;
    reg  [15:0] back_y$w;
    wire  [31:0] back_y$y;
    reg  [63:0] sat_x$v;
    wire  [31:0] sat_x$y;
    reg  [63:0] sat_y$v;
    wire  [31:0] sat_y$y;
    reg  [63:0] sat_z$v;
    wire  [31:0] sat_z$y;
    reg  [31:0] gx_out$d;
    wire  [31:0] gx_out$q;
    reg  gx_out$clock;
    reg  [31:0] gy_out$d;
    wire  [31:0] gy_out$q;
    reg  gy_out$clock;
    reg  [31:0] gz_out$d;
    wire  [31:0] gz_out$q;
    reg  gz_out$clock;
    reg  [31:0] centre_q$0$d;
    wire  [31:0] centre_q$0$q;
    reg  centre_q$0$clock;
    reg  [31:0] centre_q$1$d;
    wire  [31:0] centre_q$1$q;
    reg  centre_q$1$clock;
    reg  [31:0] centre_q$2$d;
    wire  [31:0] centre_q$2$q;
    reg  centre_q$2$clock;
    reg  [31:0] centre_q$3$d;
    wire  [31:0] centre_q$3$q;
    reg  centre_q$3$clock;
    reg  [31:0] centre_q$4$d;
    wire  [31:0] centre_q$4$q;
    reg  centre_q$4$clock;
    reg  [31:0] centre_q$5$d;
    wire  [31:0] centre_q$5$q;
    reg  centre_q$5$clock;
    reg  [31:0] centre_q$6$d;
    wire  [31:0] centre_q$6$q;
    reg  centre_q$6$clock;
    
    // Local signals
    reg  [63:0] shear_sum;
    reg  [63:0] shear;
    reg  sx_pos;
    reg  sx_neg;
    reg  sy_pos;
    reg  sy_neg;
    reg  [31:0] front_row$0;
    reg  [31:0] front_row$1;
    reg  [31:0] front_row$2;
    reg  [31:0] back_row$0;
    reg  [31:0] back_row$1;
    reg  [31:0] back_row$2;
    reg  [31:0] front_x;
    reg  [31:0] front_xy;
    reg  [31:0] back_x;
    reg  [31:0] back_xy;
    reg  [63:0] gr_wide;
    reg  [63:0] gz_wide;
    
    // Sub module instances
    top$pipeline$abc$estimators$0$b10x_q$0 b10x_q$0(
        .d(b10x_q$0$d),
        .q(b10x_q$0$q),
        .clock(b10x_q$0$clock)
    );
    top$pipeline$abc$estimators$0$b10x_q$1 b10x_q$1(
        .d(b10x_q$1$d),
        .q(b10x_q$1$q),
        .clock(b10x_q$1$clock)
    );
    top$pipeline$abc$estimators$0$b10y_q$0 b10y_q$0(
        .d(b10y_q$0$d),
        .q(b10y_q$0$q),
        .clock(b10y_q$0$clock)
    );
    top$pipeline$abc$estimators$0$b10y_q$1 b10y_q$1(
        .d(b10y_q$1$d),
        .q(b10y_q$1$q),
        .clock(b10y_q$1$clock)
    );
    top$pipeline$abc$estimators$0$b10z_q$0 b10z_q$0(
        .d(b10z_q$0$d),
        .q(b10z_q$0$q),
        .clock(b10z_q$0$clock)
    );
    top$pipeline$abc$estimators$0$b10z_q$1 b10z_q$1(
        .d(b10z_q$1$d),
        .q(b10z_q$1$q),
        .clock(b10z_q$1$clock)
    );
    top$pipeline$abc$estimators$0$gx_q$0 gx_q$0(
        .d(gx_q$0$d),
        .q(gx_q$0$q),
        .clock(gx_q$0$clock)
    );
    top$pipeline$abc$estimators$0$gx_q$1 gx_q$1(
        .d(gx_q$1$d),
        .q(gx_q$1$q),
        .clock(gx_q$1$clock)
    );
    top$pipeline$abc$estimators$0$gx_q$2 gx_q$2(
        .d(gx_q$2$d),
        .q(gx_q$2$q),
        .clock(gx_q$2$clock)
    );
    top$pipeline$abc$estimators$0$gx_q$3 gx_q$3(
        .d(gx_q$3$d),
        .q(gx_q$3$q),
        .clock(gx_q$3$clock)
    );
    top$pipeline$abc$estimators$0$gx_q$4 gx_q$4(
        .d(gx_q$4$d),
        .q(gx_q$4$q),
        .clock(gx_q$4$clock)
    );
    top$pipeline$abc$estimators$0$gx_q$5 gx_q$5(
        .d(gx_q$5$d),
        .q(gx_q$5$q),
        .clock(gx_q$5$clock)
    );
    top$pipeline$abc$estimators$0$gy_q$0 gy_q$0(
        .d(gy_q$0$d),
        .q(gy_q$0$q),
        .clock(gy_q$0$clock)
    );
    top$pipeline$abc$estimators$0$gy_q$1 gy_q$1(
        .d(gy_q$1$d),
        .q(gy_q$1$q),
        .clock(gy_q$1$clock)
    );
    top$pipeline$abc$estimators$0$gy_q$2 gy_q$2(
        .d(gy_q$2$d),
        .q(gy_q$2$q),
        .clock(gy_q$2$clock)
    );
    top$pipeline$abc$estimators$0$gy_q$3 gy_q$3(
        .d(gy_q$3$d),
        .q(gy_q$3$q),
        .clock(gy_q$3$clock)
    );
    top$pipeline$abc$estimators$0$gy_q$4 gy_q$4(
        .d(gy_q$4$d),
        .q(gy_q$4$q),
        .clock(gy_q$4$clock)
    );
    top$pipeline$abc$estimators$0$gy_q$5 gy_q$5(
        .d(gy_q$5$d),
        .q(gy_q$5$q),
        .clock(gy_q$5$clock)
    );
    top$pipeline$abc$estimators$0$gr_q$0 gr_q$0(
        .d(gr_q$0$d),
        .q(gr_q$0$q),
        .clock(gr_q$0$clock)
    );
    top$pipeline$abc$estimators$0$gr_q$1 gr_q$1(
        .d(gr_q$1$d),
        .q(gr_q$1$q),
        .clock(gr_q$1$clock)
    );
    top$pipeline$abc$estimators$0$gr_q$2 gr_q$2(
        .d(gr_q$2$d),
        .q(gr_q$2$q),
        .clock(gr_q$2$clock)
    );
    top$pipeline$abc$estimators$0$gr_q$3 gr_q$3(
        .d(gr_q$3$d),
        .q(gr_q$3$q),
        .clock(gr_q$3$clock)
    );
    top$pipeline$abc$estimators$0$gr_q$4 gr_q$4(
        .d(gr_q$4$d),
        .q(gr_q$4$q),
        .clock(gr_q$4$clock)
    );
    top$pipeline$abc$estimators$0$gr_q$5 gr_q$5(
        .d(gr_q$5$d),
        .q(gr_q$5$q),
        .clock(gr_q$5$clock)
    );
    top$pipeline$abc$estimators$0$dx_neg_q$0 dx_neg_q$0(
        .d(dx_neg_q$0$d),
        .q(dx_neg_q$0$q),
        .clock(dx_neg_q$0$clock)
    );
    top$pipeline$abc$estimators$0$dx_neg_q$1 dx_neg_q$1(
        .d(dx_neg_q$1$d),
        .q(dx_neg_q$1$q),
        .clock(dx_neg_q$1$clock)
    );
    top$pipeline$abc$estimators$0$dx_neg_q$2 dx_neg_q$2(
        .d(dx_neg_q$2$d),
        .q(dx_neg_q$2$q),
        .clock(dx_neg_q$2$clock)
    );
    top$pipeline$abc$estimators$0$dx_neg_q$3 dx_neg_q$3(
        .d(dx_neg_q$3$d),
        .q(dx_neg_q$3$q),
        .clock(dx_neg_q$3$clock)
    );
    top$pipeline$abc$estimators$0$dx_neg_q$4 dx_neg_q$4(
        .d(dx_neg_q$4$d),
        .q(dx_neg_q$4$q),
        .clock(dx_neg_q$4$clock)
    );
    top$pipeline$abc$estimators$0$dx_mag_q$0 dx_mag_q$0(
        .d(dx_mag_q$0$d),
        .q(dx_mag_q$0$q),
        .clock(dx_mag_q$0$clock)
    );
    top$pipeline$abc$estimators$0$dx_mag_q$1 dx_mag_q$1(
        .d(dx_mag_q$1$d),
        .q(dx_mag_q$1$q),
        .clock(dx_mag_q$1$clock)
    );
    top$pipeline$abc$estimators$0$dx_mag_q$2 dx_mag_q$2(
        .d(dx_mag_q$2$d),
        .q(dx_mag_q$2$q),
        .clock(dx_mag_q$2$clock)
    );
    top$pipeline$abc$estimators$0$dx_mag_q$3 dx_mag_q$3(
        .d(dx_mag_q$3$d),
        .q(dx_mag_q$3$q),
        .clock(dx_mag_q$3$clock)
    );
    top$pipeline$abc$estimators$0$dx_mag_q$4 dx_mag_q$4(
        .d(dx_mag_q$4$d),
        .q(dx_mag_q$4$q),
        .clock(dx_mag_q$4$clock)
    );
    top$pipeline$abc$estimators$0$dy_neg_q$0 dy_neg_q$0(
        .d(dy_neg_q$0$d),
        .q(dy_neg_q$0$q),
        .clock(dy_neg_q$0$clock)
    );
    top$pipeline$abc$estimators$0$dy_neg_q$1 dy_neg_q$1(
        .d(dy_neg_q$1$d),
        .q(dy_neg_q$1$q),
        .clock(dy_neg_q$1$clock)
    );
    top$pipeline$abc$estimators$0$dy_neg_q$2 dy_neg_q$2(
        .d(dy_neg_q$2$d),
        .q(dy_neg_q$2$q),
        .clock(dy_neg_q$2$clock)
    );
    top$pipeline$abc$estimators$0$dy_neg_q$3 dy_neg_q$3(
        .d(dy_neg_q$3$d),
        .q(dy_neg_q$3$q),
        .clock(dy_neg_q$3$clock)
    );
    top$pipeline$abc$estimators$0$dy_neg_q$4 dy_neg_q$4(
        .d(dy_neg_q$4$d),
        .q(dy_neg_q$4$q),
        .clock(dy_neg_q$4$clock)
    );
    top$pipeline$abc$estimators$0$dy_mag_q$0 dy_mag_q$0(
        .d(dy_mag_q$0$d),
        .q(dy_mag_q$0$q),
        .clock(dy_mag_q$0$clock)
    );
    top$pipeline$abc$estimators$0$dy_mag_q$1 dy_mag_q$1(
        .d(dy_mag_q$1$d),
        .q(dy_mag_q$1$q),
        .clock(dy_mag_q$1$clock)
    );
    top$pipeline$abc$estimators$0$dy_mag_q$2 dy_mag_q$2(
        .d(dy_mag_q$2$d),
        .q(dy_mag_q$2$q),
        .clock(dy_mag_q$2$clock)
    );
    top$pipeline$abc$estimators$0$dy_mag_q$3 dy_mag_q$3(
        .d(dy_mag_q$3$d),
        .q(dy_mag_q$3$q),
        .clock(dy_mag_q$3$clock)
    );
    top$pipeline$abc$estimators$0$dy_mag_q$4 dy_mag_q$4(
        .d(dy_mag_q$4$d),
        .q(dy_mag_q$4$q),
        .clock(dy_mag_q$4$clock)
    );
    top$pipeline$abc$estimators$0$px px(
        .g(px$g),
        .d_neg(px$d_neg),
        .d_mag(px$d_mag),
        .y(px$y)
    );
    top$pipeline$abc$estimators$0$py py(
        .g(py$g),
        .d_neg(py$d_neg),
        .d_mag(py$d_mag),
        .y(py$y)
    );
    top$pipeline$abc$estimators$0$px_q px_q(
        .d(px_q$d),
        .q(px_q$q),
        .clock(px_q$clock)
    );
    top$pipeline$abc$estimators$0$py_q py_q(
        .d(py_q$d),
        .q(py_q$q),
        .clock(py_q$clock)
    );
    top$pipeline$abc$estimators$0$front_top front_top(
        .clock(front_top$clock),
        .a(front_top$a),
        .b(front_top$b),
        .w(front_top$w),
        .y(front_top$y)
    );
    top$pipeline$abc$estimators$0$front_bottom front_bottom(
        .clock(front_bottom$clock),
        .a(front_bottom$a),
        .b(front_bottom$b),
        .w(front_bottom$w),
        .y(front_bottom$y)
    );
    top$pipeline$abc$estimators$0$front_y front_y(
        .clock(front_y$clock),
        .a(front_y$a),
        .b(front_y$b),
        .w(front_y$w),
        .y(front_y$y)
    );
    top$pipeline$abc$estimators$0$back_top back_top(
        .clock(back_top$clock),
        .a(back_top$a),
        .b(back_top$b),
        .w(back_top$w),
        .y(back_top$y)
    );
    top$pipeline$abc$estimators$0$back_bottom back_bottom(
        .clock(back_bottom$clock),
        .a(back_bottom$a),
        .b(back_bottom$b),
        .w(back_bottom$w),
        .y(back_bottom$y)
    );
    top$pipeline$abc$estimators$0$back_y back_y(
        .clock(back_y$clock),
        .a(back_y$a),
        .b(back_y$b),
        .w(back_y$w),
        .y(back_y$y)
    );
    top$pipeline$abc$estimators$0$sat_x sat_x(
        .v(sat_x$v),
        .y(sat_x$y)
    );
    top$pipeline$abc$estimators$0$sat_y sat_y(
        .v(sat_y$v),
        .y(sat_y$y)
    );
    top$pipeline$abc$estimators$0$sat_z sat_z(
        .v(sat_z$v),
        .y(sat_z$y)
    );
    top$pipeline$abc$estimators$0$gx_out gx_out(
        .d(gx_out$d),
        .q(gx_out$q),
        .clock(gx_out$clock)
    );
    top$pipeline$abc$estimators$0$gy_out gy_out(
        .d(gy_out$d),
        .q(gy_out$q),
        .clock(gy_out$clock)
    );
    top$pipeline$abc$estimators$0$gz_out gz_out(
        .d(gz_out$d),
        .q(gz_out$q),
        .clock(gz_out$clock)
    );
    top$pipeline$abc$estimators$0$centre_q$0 centre_q$0(
        .d(centre_q$0$d),
        .q(centre_q$0$q),
        .clock(centre_q$0$clock)
    );
    top$pipeline$abc$estimators$0$centre_q$1 centre_q$1(
        .d(centre_q$1$d),
        .q(centre_q$1$q),
        .clock(centre_q$1$clock)
    );
    top$pipeline$abc$estimators$0$centre_q$2 centre_q$2(
        .d(centre_q$2$d),
        .q(centre_q$2$q),
        .clock(centre_q$2$clock)
    );
    top$pipeline$abc$estimators$0$centre_q$3 centre_q$3(
        .d(centre_q$3$d),
        .q(centre_q$3$q),
        .clock(centre_q$3$clock)
    );
    top$pipeline$abc$estimators$0$centre_q$4 centre_q$4(
        .d(centre_q$4$d),
        .q(centre_q$4$q),
        .clock(centre_q$4$clock)
    );
    top$pipeline$abc$estimators$0$centre_q$5 centre_q$5(
        .d(centre_q$5$d),
        .q(centre_q$5$q),
        .clock(centre_q$5$clock)
    );
    top$pipeline$abc$estimators$0$centre_q$6 centre_q$6(
        .d(centre_q$6$d),
        .q(centre_q$6$q),
        .clock(centre_q$6$clock)
    );
    
    // Update code
    always @(*) begin
        px_q$clock = clock;
        py_q$clock = clock;
        gx_out$clock = clock;
        gy_out$clock = clock;
        gz_out$clock = clock;
        px_q$d = px_q$q;
        py_q$d = py_q$q;
        gx_out$d = gx_out$q;
        gy_out$d = gy_out$q;
        gz_out$d = gz_out$q;
        centre_q$0$clock = clock;
        centre_q$1$clock = clock;
        centre_q$2$clock = clock;
        centre_q$3$clock = clock;
        centre_q$4$clock = clock;
        centre_q$5$clock = clock;
        centre_q$6$clock = clock;
        centre_q$0$d = centre;
        centre_q$1$d = centre_q$0$q;
        centre_q$2$d = centre_q$1$q;
        centre_q$3$d = centre_q$2$q;
        centre_q$4$d = centre_q$3$q;
        centre_q$5$d = centre_q$4$q;
        centre_q$6$d = centre_q$5$q;
        sample = centre_q$6$q;
        gx_q$0$clock = clock;
        gy_q$0$clock = clock;
        gr_q$0$clock = clock;
        gx_q$1$clock = clock;
        gy_q$1$clock = clock;
        gr_q$1$clock = clock;
        gx_q$2$clock = clock;
        gy_q$2$clock = clock;
        gr_q$2$clock = clock;
        gx_q$3$clock = clock;
        gy_q$3$clock = clock;
        gr_q$3$clock = clock;
        gx_q$4$clock = clock;
        gy_q$4$clock = clock;
        gr_q$4$clock = clock;
        gx_q$5$clock = clock;
        gy_q$5$clock = clock;
        gr_q$5$clock = clock;
        b10x_q$0$clock = clock;
        b10y_q$0$clock = clock;
        b10z_q$0$clock = clock;
        b10x_q$1$clock = clock;
        b10y_q$1$clock = clock;
        b10z_q$1$clock = clock;
        dx_neg_q$0$clock = clock;
        dx_mag_q$0$clock = clock;
        dy_neg_q$0$clock = clock;
        dy_mag_q$0$clock = clock;
        dx_neg_q$1$clock = clock;
        dx_mag_q$1$clock = clock;
        dy_neg_q$1$clock = clock;
        dy_mag_q$1$clock = clock;
        dx_neg_q$2$clock = clock;
        dx_mag_q$2$clock = clock;
        dy_neg_q$2$clock = clock;
        dy_mag_q$2$clock = clock;
        dx_neg_q$3$clock = clock;
        dx_mag_q$3$clock = clock;
        dy_neg_q$3$clock = clock;
        dy_mag_q$3$clock = clock;
        dx_neg_q$4$clock = clock;
        dx_mag_q$4$clock = clock;
        dy_neg_q$4$clock = clock;
        dy_mag_q$4$clock = clock;
        front_top$clock = clock;
        front_bottom$clock = clock;
        front_y$clock = clock;
        back_top$clock = clock;
        back_bottom$clock = clock;
        back_y$clock = clock;
        gx_q$0$d = xp - xm;
        gy_q$0$d = yp - ym;
        gr_q$0$d = kp4 - km4;
        gx_q$1$d = gx_q$0$q;
        gy_q$1$d = gy_q$0$q;
        gr_q$1$d = gr_q$0$q;
        gx_q$2$d = gx_q$1$q;
        gy_q$2$d = gy_q$1$q;
        gr_q$2$d = gr_q$1$q;
        gx_q$3$d = gx_q$2$q;
        gy_q$3$d = gy_q$2$q;
        gr_q$3$d = gr_q$2$q;
        gx_q$4$d = gx_q$3$q;
        gy_q$4$d = gy_q$3$q;
        gr_q$4$d = gr_q$3$q;
        gx_q$5$d = gx_q$4$q;
        gy_q$5$d = gy_q$4$q;
        gr_q$5$d = gr_q$4$q;
        sums26$clock = clock;
        sums26$xp = xp;
        sums26$xm = xm;
        sums26$yp = yp;
        sums26$ym = ym;
        sums26$c0 = c0;
        sums26$c2 = c2;
        sums26$c6 = c6;
        sums26$c8 = c8;
        sums26$kp0 = kp0;
        sums26$kp1 = kp1;
        sums26$kp2 = kp2;
        sums26$kp3 = kp3;
        sums26$kp4 = kp4;
        sums26$kp5 = kp5;
        sums26$kp6 = kp6;
        sums26$kp7 = kp7;
        sums26$kp8 = kp8;
        sums26$km0 = km0;
        sums26$km1 = km1;
        sums26$km2 = km2;
        sums26$km3 = km3;
        sums26$km4 = km4;
        sums26$km5 = km5;
        sums26$km6 = km6;
        sums26$km7 = km7;
        sums26$km8 = km8;
        basis10$clock = clock;
        basis10$xp = xp;
        basis10$xm = xm;
        basis10$yp = yp;
        basis10$ym = ym;
        basis10$kp1 = kp1;
        basis10$kp3 = kp3;
        basis10$kp4 = kp4;
        basis10$kp5 = kp5;
        basis10$kp7 = kp7;
        basis10$km1 = km1;
        basis10$km3 = km3;
        basis10$km4 = km4;
        basis10$km5 = km5;
        basis10$km7 = km7;
        basis10$dx_neg = dx_neg;
        basis10$dx_mag = dx_mag;
        basis10$dy_neg = dy_neg;
        basis10$dy_mag = dy_mag;
        basis10$weights = weights10;
        basis10$basis_x = basis10_x;
        basis10$basis_y = basis10_y;
        basis10$basis_z = basis10_z;
        if (n26) begin
            gx_q$2$d = sums26$gx;
            gy_q$2$d = sums26$gy;
            gr_q$2$d = sums26$gr;
        end
        dx_neg_q$0$d = dx_neg;
        dx_mag_q$0$d = dx_mag;
        dy_neg_q$0$d = dy_neg;
        dy_mag_q$0$d = dy_mag;
        dx_neg_q$1$d = dx_neg_q$0$q;
        dx_mag_q$1$d = dx_mag_q$0$q;
        dy_neg_q$1$d = dy_neg_q$0$q;
        dy_mag_q$1$d = dy_mag_q$0$q;
        dx_neg_q$2$d = dx_neg_q$1$q;
        dx_mag_q$2$d = dx_mag_q$1$q;
        dy_neg_q$2$d = dy_neg_q$1$q;
        dy_mag_q$2$d = dy_mag_q$1$q;
        dx_neg_q$3$d = dx_neg_q$2$q;
        dx_mag_q$3$d = dx_mag_q$2$q;
        dy_neg_q$3$d = dy_neg_q$2$q;
        dy_mag_q$3$d = dy_mag_q$2$q;
        dx_neg_q$4$d = dx_neg_q$3$q;
        dx_mag_q$4$d = dx_mag_q$3$q;
        dy_neg_q$4$d = dy_neg_q$3$q;
        dy_mag_q$4$d = dy_mag_q$3$q;
        px$g = gx_q$4$q;
        px$d_neg = dx_neg_q$4$q;
        px$d_mag = dx_mag_q$4$q;
        py$g = gy_q$4$q;
        py$d_neg = dy_neg_q$4$q;
        py$d_mag = dy_mag_q$4$q;
        px_q$d = px$y;
        py_q$d = py$y;
        shear_sum = px_q$q + py_q$q + half;
        shear = shear_sum >> shift;
        if (shear_sum['h3f]) begin
            shear = ~((~shear_sum) >> shift);
        end
        sx_pos = ~dx_neg & |dx_mag;
        sx_neg = dx_neg & |dx_mag;
        sy_pos = ~dy_neg & |dy_mag;
        sy_neg = dy_neg & |dy_mag;
        front_row$0 = kp3;
        back_row$0 = km3;
        if (sy_pos) begin
            front_row$0 = kp6;
            back_row$0 = km0;
        end
        if (sy_neg) begin
            front_row$0 = kp0;
            back_row$0 = km6;
        end
        front_row$1 = kp4;
        back_row$1 = km4;
        if (sy_pos) begin
            front_row$1 = kp7;
            back_row$1 = km1;
        end
        if (sy_neg) begin
            front_row$1 = kp1;
            back_row$1 = km7;
        end
        front_row$2 = kp5;
        back_row$2 = km5;
        if (sy_pos) begin
            front_row$2 = kp8;
            back_row$2 = km2;
        end
        if (sy_neg) begin
            front_row$2 = kp2;
            back_row$2 = km8;
        end
        front_x = kp4;
        front_xy = front_row$1;
        back_x = km4;
        back_xy = back_row$1;
        if (sx_pos) begin
            front_x = kp5;
            front_xy = front_row$2;
            back_x = km3;
            back_xy = back_row$0;
        end
        if (sx_neg) begin
            front_x = kp3;
            front_xy = front_row$0;
            back_x = km5;
            back_xy = back_row$2;
        end
        front_top$a = kp4;
        front_top$b = front_x;
        front_top$w = dx_mag;
        front_bottom$a = front_row$1;
        front_bottom$b = front_xy;
        front_bottom$w = dx_mag;
        front_y$a = front_top$y;
        front_y$b = front_bottom$y;
        front_y$w = dy_mag_q$2$q;
        back_top$a = km4;
        back_top$b = back_x;
        back_top$w = dx_mag;
        back_bottom$a = back_row$1;
        back_bottom$b = back_xy;
        back_bottom$w = dx_mag;
        back_y$a = back_top$y;
        back_y$b = back_bottom$y;
        back_y$w = dy_mag_q$2$q;
        gr_wide = 64'(gr_q$5$q);
        if (gr_q$5$q['h1f]) begin
            gr_wide = 64'(gr_q$5$q) | sign_ext;
        end
        gz_wide = gr_wide - shear;
        if (n12) begin
            gz_wide = 64'(front_y$y) - 64'(back_y$y);
        end
        sat_x$v = 64'(gx_q$5$q);
        if (gx_q$5$q['h1f]) begin
            sat_x$v = 64'(gx_q$5$q) | sign_ext;
        end
        sat_y$v = 64'(gy_q$5$q);
        if (gy_q$5$q['h1f]) begin
            sat_y$v = 64'(gy_q$5$q) | sign_ext;
        end
        sat_z$v = gz_wide;
        b10x_q$0$d = basis10$gx;
        b10y_q$0$d = basis10$gy;
        b10z_q$0$d = basis10$gz;
        b10x_q$1$d = b10x_q$0$q;
        b10y_q$1$d = b10y_q$0$q;
        b10z_q$1$d = b10z_q$0$q;
        if (n10) begin
            sat_x$v = b10x_q$1$q;
            sat_y$v = b10y_q$1$q;
            sat_z$v = b10z_q$1$q;
        end
        gx_out$d = sat_x$y;
        gy_out$d = sat_y$y;
        gz_out$d = sat_z$y;
        gx = gx_out$q;
        gy = gy_out$q;
        gz = gz_out$q;
    end
    
endmodule // top$pipeline$abc$estimators$0
module top$pipeline$abc$estimators$0$b10x_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$b10x_q$0
module top$pipeline$abc$estimators$0$b10x_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$b10x_q$1
module top$pipeline$abc$estimators$0$b10y_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$b10y_q$0
module top$pipeline$abc$estimators$0$b10y_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$b10y_q$1
module top$pipeline$abc$estimators$0$b10z_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$b10z_q$0
module top$pipeline$abc$estimators$0$b10z_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$b10z_q$1
module top$pipeline$abc$estimators$0$back_bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$0$back_bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$0$back_bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$0$back_bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$0$back_bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$0$back_bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$0$back_bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$0$back_bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$0$back_bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$0$back_bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$0$back_bottom
module top$pipeline$abc$estimators$0$back_bottom$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_bottom$a_q
module top$pipeline$abc$estimators$0$back_bottom$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_bottom$a_q2
module top$pipeline$abc$estimators$0$back_bottom$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_bottom$diff_q
module top$pipeline$abc$estimators$0$back_bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$0$back_bottom$narrow
module top$pipeline$abc$estimators$0$back_bottom$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_bottom$prod_q
module top$pipeline$abc$estimators$0$back_bottom$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_bottom$up_q
module top$pipeline$abc$estimators$0$back_bottom$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_bottom$up_q2
module top$pipeline$abc$estimators$0$back_bottom$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_bottom$w_q
module top$pipeline$abc$estimators$0$back_bottom$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_bottom$y_q
module top$pipeline$abc$estimators$0$back_top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$0$back_top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$0$back_top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$0$back_top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$0$back_top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$0$back_top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$0$back_top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$0$back_top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$0$back_top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$0$back_top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$0$back_top
module top$pipeline$abc$estimators$0$back_top$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_top$a_q
module top$pipeline$abc$estimators$0$back_top$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_top$a_q2
module top$pipeline$abc$estimators$0$back_top$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_top$diff_q
module top$pipeline$abc$estimators$0$back_top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$0$back_top$narrow
module top$pipeline$abc$estimators$0$back_top$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_top$prod_q
module top$pipeline$abc$estimators$0$back_top$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_top$up_q
module top$pipeline$abc$estimators$0$back_top$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_top$up_q2
module top$pipeline$abc$estimators$0$back_top$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_top$w_q
module top$pipeline$abc$estimators$0$back_top$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_top$y_q
module top$pipeline$abc$estimators$0$back_y(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$0$back_y$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$0$back_y$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$0$back_y$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$0$back_y$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$0$back_y$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$0$back_y$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$0$back_y$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$0$back_y$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$0$back_y$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$0$back_y
module top$pipeline$abc$estimators$0$back_y$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_y$a_q
module top$pipeline$abc$estimators$0$back_y$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_y$a_q2
module top$pipeline$abc$estimators$0$back_y$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_y$diff_q
module top$pipeline$abc$estimators$0$back_y$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$0$back_y$narrow
module top$pipeline$abc$estimators$0$back_y$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_y$prod_q
module top$pipeline$abc$estimators$0$back_y$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_y$up_q
module top$pipeline$abc$estimators$0$back_y$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_y$up_q2
module top$pipeline$abc$estimators$0$back_y$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_y$w_q
module top$pipeline$abc$estimators$0$back_y$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$back_y$y_q
module top$pipeline$abc$estimators$0$centre_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$centre_q$0
module top$pipeline$abc$estimators$0$centre_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$centre_q$1
module top$pipeline$abc$estimators$0$centre_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$centre_q$2
module top$pipeline$abc$estimators$0$centre_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$centre_q$3
module top$pipeline$abc$estimators$0$centre_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$centre_q$4
module top$pipeline$abc$estimators$0$centre_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$centre_q$5
module top$pipeline$abc$estimators$0$centre_q$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$centre_q$6
module top$pipeline$abc$estimators$0$dx_mag_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dx_mag_q$0
module top$pipeline$abc$estimators$0$dx_mag_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dx_mag_q$1
module top$pipeline$abc$estimators$0$dx_mag_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dx_mag_q$2
module top$pipeline$abc$estimators$0$dx_mag_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dx_mag_q$3
module top$pipeline$abc$estimators$0$dx_mag_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dx_mag_q$4
module top$pipeline$abc$estimators$0$dx_neg_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dx_neg_q$0
module top$pipeline$abc$estimators$0$dx_neg_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dx_neg_q$1
module top$pipeline$abc$estimators$0$dx_neg_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dx_neg_q$2
module top$pipeline$abc$estimators$0$dx_neg_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dx_neg_q$3
module top$pipeline$abc$estimators$0$dx_neg_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dx_neg_q$4
module top$pipeline$abc$estimators$0$dy_mag_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dy_mag_q$0
module top$pipeline$abc$estimators$0$dy_mag_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dy_mag_q$1
module top$pipeline$abc$estimators$0$dy_mag_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dy_mag_q$2
module top$pipeline$abc$estimators$0$dy_mag_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dy_mag_q$3
module top$pipeline$abc$estimators$0$dy_mag_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dy_mag_q$4
module top$pipeline$abc$estimators$0$dy_neg_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dy_neg_q$0
module top$pipeline$abc$estimators$0$dy_neg_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dy_neg_q$1
module top$pipeline$abc$estimators$0$dy_neg_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dy_neg_q$2
module top$pipeline$abc$estimators$0$dy_neg_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dy_neg_q$3
module top$pipeline$abc$estimators$0$dy_neg_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$dy_neg_q$4
module top$pipeline$abc$estimators$0$front_bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$0$front_bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$0$front_bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$0$front_bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$0$front_bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$0$front_bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$0$front_bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$0$front_bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$0$front_bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$0$front_bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$0$front_bottom
module top$pipeline$abc$estimators$0$front_bottom$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_bottom$a_q
module top$pipeline$abc$estimators$0$front_bottom$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_bottom$a_q2
module top$pipeline$abc$estimators$0$front_bottom$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_bottom$diff_q
module top$pipeline$abc$estimators$0$front_bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$0$front_bottom$narrow
module top$pipeline$abc$estimators$0$front_bottom$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_bottom$prod_q
module top$pipeline$abc$estimators$0$front_bottom$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_bottom$up_q
module top$pipeline$abc$estimators$0$front_bottom$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_bottom$up_q2
module top$pipeline$abc$estimators$0$front_bottom$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_bottom$w_q
module top$pipeline$abc$estimators$0$front_bottom$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_bottom$y_q
module top$pipeline$abc$estimators$0$front_top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$0$front_top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$0$front_top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$0$front_top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$0$front_top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$0$front_top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$0$front_top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$0$front_top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$0$front_top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$0$front_top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$0$front_top
module top$pipeline$abc$estimators$0$front_top$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_top$a_q
module top$pipeline$abc$estimators$0$front_top$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_top$a_q2
module top$pipeline$abc$estimators$0$front_top$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_top$diff_q
module top$pipeline$abc$estimators$0$front_top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$0$front_top$narrow
module top$pipeline$abc$estimators$0$front_top$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_top$prod_q
module top$pipeline$abc$estimators$0$front_top$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_top$up_q
module top$pipeline$abc$estimators$0$front_top$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_top$up_q2
module top$pipeline$abc$estimators$0$front_top$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_top$w_q
module top$pipeline$abc$estimators$0$front_top$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_top$y_q
module top$pipeline$abc$estimators$0$front_y(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$0$front_y$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$0$front_y$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$0$front_y$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$0$front_y$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$0$front_y$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$0$front_y$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$0$front_y$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$0$front_y$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$0$front_y$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$0$front_y
module top$pipeline$abc$estimators$0$front_y$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_y$a_q
module top$pipeline$abc$estimators$0$front_y$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_y$a_q2
module top$pipeline$abc$estimators$0$front_y$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_y$diff_q
module top$pipeline$abc$estimators$0$front_y$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$0$front_y$narrow
module top$pipeline$abc$estimators$0$front_y$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_y$prod_q
module top$pipeline$abc$estimators$0$front_y$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_y$up_q
module top$pipeline$abc$estimators$0$front_y$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_y$up_q2
module top$pipeline$abc$estimators$0$front_y$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_y$w_q
module top$pipeline$abc$estimators$0$front_y$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$front_y$y_q
module top$pipeline$abc$estimators$0$gr_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gr_q$0
module top$pipeline$abc$estimators$0$gr_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gr_q$1
module top$pipeline$abc$estimators$0$gr_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gr_q$2
module top$pipeline$abc$estimators$0$gr_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gr_q$3
module top$pipeline$abc$estimators$0$gr_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gr_q$4
module top$pipeline$abc$estimators$0$gr_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gr_q$5
module top$pipeline$abc$estimators$0$gx_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gx_out
module top$pipeline$abc$estimators$0$gx_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gx_q$0
module top$pipeline$abc$estimators$0$gx_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gx_q$1
module top$pipeline$abc$estimators$0$gx_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gx_q$2
module top$pipeline$abc$estimators$0$gx_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gx_q$3
module top$pipeline$abc$estimators$0$gx_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gx_q$4
module top$pipeline$abc$estimators$0$gx_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gx_q$5
module top$pipeline$abc$estimators$0$gy_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gy_out
module top$pipeline$abc$estimators$0$gy_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gy_q$0
module top$pipeline$abc$estimators$0$gy_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gy_q$1
module top$pipeline$abc$estimators$0$gy_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gy_q$2
module top$pipeline$abc$estimators$0$gy_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gy_q$3
module top$pipeline$abc$estimators$0$gy_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gy_q$4
module top$pipeline$abc$estimators$0$gy_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gy_q$5
module top$pipeline$abc$estimators$0$gz_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$gz_out
module top$pipeline$abc$estimators$0$px(g,d_neg,d_mag,y);
    
    // Module arguments
    input wire  [31:0] g;
    input wire  d_neg;
    input wire  [15:0] d_mag;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] mag;
    reg  [63:0] prod;
    
    // Update code
    reg  [63:0] y_pass;
    always @(*) begin
        mag = g;
        if (g['h1f]) begin
            mag = ~g + 'h1;
        end
        prod = 64'(mag[('h0)+:(16)] * d_mag);
        if (wide) begin
            prod = (64'(mag[('h10)+:(16)] * d_mag) << 'h10) + 64'(mag[('h0)+:(16)] * d_mag);
        end
        y_pass = prod;
        if (g['h1f] ^ d_neg) begin
            y_pass = ~prod + 'h1;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$0$px
module top$pipeline$abc$estimators$0$px_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$px_q
module top$pipeline$abc$estimators$0$py(g,d_neg,d_mag,y);
    
    // Module arguments
    input wire  [31:0] g;
    input wire  d_neg;
    input wire  [15:0] d_mag;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] mag;
    reg  [63:0] prod;
    
    // Update code
    reg  [63:0] y_pass;
    always @(*) begin
        mag = g;
        if (g['h1f]) begin
            mag = ~g + 'h1;
        end
        prod = 64'(mag[('h0)+:(16)] * d_mag);
        if (wide) begin
            prod = (64'(mag[('h10)+:(16)] * d_mag) << 'h10) + 64'(mag[('h0)+:(16)] * d_mag);
        end
        y_pass = prod;
        if (g['h1f] ^ d_neg) begin
            y_pass = ~prod + 'h1;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$0$py
module top$pipeline$abc$estimators$0$py_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$0$py_q
module top$pipeline$abc$estimators$0$sat_x(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$0$sat_x
module top$pipeline$abc$estimators$0$sat_y(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$0$sat_y
module top$pipeline$abc$estimators$0$sat_z(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$0$sat_z
module top$pipeline$abc$estimators$1(clock,xp,xm,yp,ym,kp0,kp1,kp2,kp3,kp4,kp5,kp6,kp7,kp8,km0,km1,km2,km3,km4,km5,km6,km7,km8,c0,c2,c6,c8,weights10,basis10_x,basis10_y,basis10_z,dx_neg,dx_mag,dy_neg,dy_mag,centre,sample,gx,gy,gz);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] xp;
    input wire  [31:0] xm;
    input wire  [31:0] yp;
    input wire  [31:0] ym;
    input wire  [31:0] kp0;
    input wire  [31:0] kp1;
    input wire  [31:0] kp2;
    input wire  [31:0] kp3;
    input wire  [31:0] kp4;
    input wire  [31:0] kp5;
    input wire  [31:0] kp6;
    input wire  [31:0] kp7;
    input wire  [31:0] kp8;
    input wire  [31:0] km0;
    input wire  [31:0] km1;
    input wire  [31:0] km2;
    input wire  [31:0] km3;
    input wire  [31:0] km4;
    input wire  [31:0] km5;
    input wire  [31:0] km6;
    input wire  [31:0] km7;
    input wire  [31:0] km8;
    input wire  [31:0] c0;
    input wire  [31:0] c2;
    input wire  [31:0] c6;
    input wire  [31:0] c8;
    input wire  [63:0] weights10;
    input wire  [63:0] basis10_x;
    input wire  [63:0] basis10_y;
    input wire  [63:0] basis10_z;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [31:0] centre;
    output reg  [31:0] sample;
    output reg  [31:0] gx;
    output reg  [31:0] gy;
    output reg  [31:0] gz;
    
    // Constant declarations
    localparam  n12 = 1'b1;
    localparam  n26 = 1'b0;
    localparam  n10 = 1'b0;
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  sign_ext = 64'hffffffff00000000;
    
    // Stub signals
    reg  sums26$clock;
    reg  [31:0] sums26$xp;
    reg  [31:0] sums26$xm;
    reg  [31:0] sums26$yp;
    reg  [31:0] sums26$ym;
    reg  [31:0] sums26$c0;
    reg  [31:0] sums26$c2;
    reg  [31:0] sums26$c6;
    reg  [31:0] sums26$c8;
    reg  [31:0] sums26$kp0;
    reg  [31:0] sums26$kp1;
    reg  [31:0] sums26$kp2;
    reg  [31:0] sums26$kp3;
    reg  [31:0] sums26$kp4;
    reg  [31:0] sums26$kp5;
    reg  [31:0] sums26$kp6;
    reg  [31:0] sums26$kp7;
    reg  [31:0] sums26$kp8;
    reg  [31:0] sums26$km0;
    reg  [31:0] sums26$km1;
    reg  [31:0] sums26$km2;
    reg  [31:0] sums26$km3;
    reg  [31:0] sums26$km4;
    reg  [31:0] sums26$km5;
    reg  [31:0] sums26$km6;
    reg  [31:0] sums26$km7;
    reg  [31:0] sums26$km8;
    wire  [31:0] sums26$gx = 'h0;
    wire  [31:0] sums26$gy = 'h0;
    wire  [31:0] sums26$gr = 'h0;
    reg  basis10$clock;
    reg  [31:0] basis10$xp;
    reg  [31:0] basis10$xm;
    reg  [31:0] basis10$yp;
    reg  [31:0] basis10$ym;
    reg  [31:0] basis10$kp1;
    reg  [31:0] basis10$kp3;
    reg  [31:0] basis10$kp4;
    reg  [31:0] basis10$kp5;
    reg  [31:0] basis10$kp7;
    reg  [31:0] basis10$km1;
    reg  [31:0] basis10$km3;
    reg  [31:0] basis10$km4;
    reg  [31:0] basis10$km5;
    reg  [31:0] basis10$km7;
    reg  basis10$dx_neg;
    reg  [15:0] basis10$dx_mag;
    reg  basis10$dy_neg;
    reg  [15:0] basis10$dy_mag;
    reg  [63:0] basis10$weights;
    reg  [63:0] basis10$basis_x;
    reg  [63:0] basis10$basis_y;
    reg  [63:0] basis10$basis_z;
    wire  [63:0] basis10$gx = 'h0;
    wire  [63:0] basis10$gy = 'h0;
    wire  [63:0] basis10$gz = 'h0;
    reg  [63:0] b10x_q$0$d;
    wire  [63:0] b10x_q$0$q;
    reg  b10x_q$0$clock;
    reg  [63:0] b10x_q$1$d;
    wire  [63:0] b10x_q$1$q;
    reg  b10x_q$1$clock;
    reg  [63:0] b10y_q$0$d;
    wire  [63:0] b10y_q$0$q;
    reg  b10y_q$0$clock;
    reg  [63:0] b10y_q$1$d;
    wire  [63:0] b10y_q$1$q;
    reg  b10y_q$1$clock;
    reg  [63:0] b10z_q$0$d;
    wire  [63:0] b10z_q$0$q;
    reg  b10z_q$0$clock;
    reg  [63:0] b10z_q$1$d;
    wire  [63:0] b10z_q$1$q;
    reg  b10z_q$1$clock;
    reg  [31:0] gx_q$0$d;
    wire  [31:0] gx_q$0$q;
    reg  gx_q$0$clock;
    reg  [31:0] gx_q$1$d;
    wire  [31:0] gx_q$1$q;
    reg  gx_q$1$clock;
    reg  [31:0] gx_q$2$d;
    wire  [31:0] gx_q$2$q;
    reg  gx_q$2$clock;
    reg  [31:0] gx_q$3$d;
    wire  [31:0] gx_q$3$q;
    reg  gx_q$3$clock;
    reg  [31:0] gx_q$4$d;
    wire  [31:0] gx_q$4$q;
    reg  gx_q$4$clock;
    reg  [31:0] gx_q$5$d;
    wire  [31:0] gx_q$5$q;
    reg  gx_q$5$clock;
    reg  [31:0] gy_q$0$d;
    wire  [31:0] gy_q$0$q;
    reg  gy_q$0$clock;
    reg  [31:0] gy_q$1$d;
    wire  [31:0] gy_q$1$q;
    reg  gy_q$1$clock;
    reg  [31:0] gy_q$2$d;
    wire  [31:0] gy_q$2$q;
    reg  gy_q$2$clock;
    reg  [31:0] gy_q$3$d;
    wire  [31:0] gy_q$3$q;
    reg  gy_q$3$clock;
    reg  [31:0] gy_q$4$d;
    wire  [31:0] gy_q$4$q;
    reg  gy_q$4$clock;
    reg  [31:0] gy_q$5$d;
    wire  [31:0] gy_q$5$q;
    reg  gy_q$5$clock;
    reg  [31:0] gr_q$0$d;
    wire  [31:0] gr_q$0$q;
    reg  gr_q$0$clock;
    reg  [31:0] gr_q$1$d;
    wire  [31:0] gr_q$1$q;
    reg  gr_q$1$clock;
    reg  [31:0] gr_q$2$d;
    wire  [31:0] gr_q$2$q;
    reg  gr_q$2$clock;
    reg  [31:0] gr_q$3$d;
    wire  [31:0] gr_q$3$q;
    reg  gr_q$3$clock;
    reg  [31:0] gr_q$4$d;
    wire  [31:0] gr_q$4$q;
    reg  gr_q$4$clock;
    reg  [31:0] gr_q$5$d;
    wire  [31:0] gr_q$5$q;
    reg  gr_q$5$clock;
    reg  dx_neg_q$0$d;
    wire  dx_neg_q$0$q;
    reg  dx_neg_q$0$clock;
    reg  dx_neg_q$1$d;
    wire  dx_neg_q$1$q;
    reg  dx_neg_q$1$clock;
    reg  dx_neg_q$2$d;
    wire  dx_neg_q$2$q;
    reg  dx_neg_q$2$clock;
    reg  dx_neg_q$3$d;
    wire  dx_neg_q$3$q;
    reg  dx_neg_q$3$clock;
    reg  dx_neg_q$4$d;
    wire  dx_neg_q$4$q;
    reg  dx_neg_q$4$clock;
    reg  [15:0] dx_mag_q$0$d;
    wire  [15:0] dx_mag_q$0$q;
    reg  dx_mag_q$0$clock;
    reg  [15:0] dx_mag_q$1$d;
    wire  [15:0] dx_mag_q$1$q;
    reg  dx_mag_q$1$clock;
    reg  [15:0] dx_mag_q$2$d;
    wire  [15:0] dx_mag_q$2$q;
    reg  dx_mag_q$2$clock;
    reg  [15:0] dx_mag_q$3$d;
    wire  [15:0] dx_mag_q$3$q;
    reg  dx_mag_q$3$clock;
    reg  [15:0] dx_mag_q$4$d;
    wire  [15:0] dx_mag_q$4$q;
    reg  dx_mag_q$4$clock;
    reg  dy_neg_q$0$d;
    wire  dy_neg_q$0$q;
    reg  dy_neg_q$0$clock;
    reg  dy_neg_q$1$d;
    wire  dy_neg_q$1$q;
    reg  dy_neg_q$1$clock;
    reg  dy_neg_q$2$d;
    wire  dy_neg_q$2$q;
    reg  dy_neg_q$2$clock;
    reg  dy_neg_q$3$d;
    wire  dy_neg_q$3$q;
    reg  dy_neg_q$3$clock;
    reg  dy_neg_q$4$d;
    wire  dy_neg_q$4$q;
    reg  dy_neg_q$4$clock;
    reg  [15:0] dy_mag_q$0$d;
    wire  [15:0] dy_mag_q$0$q;
    reg  dy_mag_q$0$clock;
    reg  [15:0] dy_mag_q$1$d;
    wire  [15:0] dy_mag_q$1$q;
    reg  dy_mag_q$1$clock;
    reg  [15:0] dy_mag_q$2$d;
    wire  [15:0] dy_mag_q$2$q;
    reg  dy_mag_q$2$clock;
    reg  [15:0] dy_mag_q$3$d;
    wire  [15:0] dy_mag_q$3$q;
    reg  dy_mag_q$3$clock;
    reg  [15:0] dy_mag_q$4$d;
    wire  [15:0] dy_mag_q$4$q;
    reg  dy_mag_q$4$clock;
    reg  [31:0] px$g;
    reg  px$d_neg;
    reg  [15:0] px$d_mag;
    wire  [63:0] px$y;
    reg  [31:0] py$g;
    reg  py$d_neg;
    reg  [15:0] py$d_mag;
    wire  [63:0] py$y;
    reg  [63:0] px_q$d;
    wire  [63:0] px_q$q;
    reg  px_q$clock;
    reg  [63:0] py_q$d;
    wire  [63:0] py_q$q;
    reg  py_q$clock;
    reg  front_top$clock;
    reg  [31:0] front_top$a;
    reg  [31:0] front_top$b;
    reg  [15:0] front_top$w;
    wire  [31:0] front_top$y;
    reg  front_bottom$clock;
    reg  [31:0] front_bottom$a;
    reg  [31:0] front_bottom$b;
    reg  [15:0] front_bottom$w;
    wire  [31:0] front_bottom$y;
    reg  front_y$clock;
    reg  [31:0] front_y$a;
    reg  [31:0] front_y$b;
    reg  [15:0] front_y$w;
    wire  [31:0] front_y$y;
    reg  back_top$clock;
    reg  [31:0] back_top$a;
    reg  [31:0] back_top$b;
    reg  [15:0] back_top$w;
    wire  [31:0] back_top$y;
    reg  back_bottom$clock;
    reg  [31:0] back_bottom$a;
    reg  [31:0] back_bottom$b;
    reg  [15:0] back_bottom$w;
    wire  [31:0] back_bottom$y;
    reg  back_y$clock;
    reg  [31:0] back_y$a;
    reg  [31:0] back_y$b;
    reg  [15:0] back_y$w;
    wire  [31:0] back_y$y;
    reg  [63:0] sat_x$v;
    wire  [31:0] sat_x$y;
    reg  [63:0] sat_y$v;
    wire  [31:0] sat_y$y;
    reg  [63:0] sat_z$v;
    wire  [31:0] sat_z$y;
    reg  [31:0] gx_out$d;
    wire  [31:0] gx_out$q;
    reg  gx_out$clock;
    reg  [31:0] gy_out$d;
    wire  [31:0] gy_out$q;
    reg  gy_out$clock;
    reg  [31:0] gz_out$d;
    wire  [31:0] gz_out$q;
    reg  gz_out$clock;
    reg  [31:0] centre_q$0$d;
    wire  [31:0] centre_q$0$q;
    reg  centre_q$0$clock;
    reg  [31:0] centre_q$1$d;
    wire  [31:0] centre_q$1$q;
    reg  centre_q$1$clock;
    reg  [31:0] centre_q$2$d;
    wire  [31:0] centre_q$2$q;
    reg  centre_q$2$clock;
    reg  [31:0] centre_q$3$d;
    wire  [31:0] centre_q$3$q;
    reg  centre_q$3$clock;
    reg  [31:0] centre_q$4$d;
    wire  [31:0] centre_q$4$q;
    reg  centre_q$4$clock;
    reg  [31:0] centre_q$5$d;
    wire  [31:0] centre_q$5$q;
    reg  centre_q$5$clock;
    reg  [31:0] centre_q$6$d;
    wire  [31:0] centre_q$6$q;
    reg  centre_q$6$clock;
    
    // Local signals
    reg  [63:0] shear_sum;
    reg  [63:0] shear;
    reg  sx_pos;
    reg  sx_neg;
    reg  sy_pos;
    reg  sy_neg;
    reg  [31:0] front_row$0;
    reg  [31:0] front_row$1;
    reg  [31:0] front_row$2;
    reg  [31:0] back_row$0;
    reg  [31:0] back_row$1;
    reg  [31:0] back_row$2;
    reg  [31:0] front_x;
    reg  [31:0] front_xy;
    reg  [31:0] back_x;
    reg  [31:0] back_xy;
    reg  [63:0] gr_wide;
    reg  [63:0] gz_wide;
    
    // Sub module instances
    top$pipeline$abc$estimators$1$b10x_q$0 b10x_q$0(
        .d(b10x_q$0$d),
        .q(b10x_q$0$q),
        .clock(b10x_q$0$clock)
    );
    top$pipeline$abc$estimators$1$b10x_q$1 b10x_q$1(
        .d(b10x_q$1$d),
        .q(b10x_q$1$q),
        .clock(b10x_q$1$clock)
    );
    top$pipeline$abc$estimators$1$b10y_q$0 b10y_q$0(
        .d(b10y_q$0$d),
        .q(b10y_q$0$q),
        .clock(b10y_q$0$clock)
    );
    top$pipeline$abc$estimators$1$b10y_q$1 b10y_q$1(
        .d(b10y_q$1$d),
        .q(b10y_q$1$q),
        .clock(b10y_q$1$clock)
    );
    top$pipeline$abc$estimators$1$b10z_q$0 b10z_q$0(
        .d(b10z_q$0$d),
        .q(b10z_q$0$q),
        .clock(b10z_q$0$clock)
    );
    top$pipeline$abc$estimators$1$b10z_q$1 b10z_q$1(
        .d(b10z_q$1$d),
        .q(b10z_q$1$q),
        .clock(b10z_q$1$clock)
    );
    top$pipeline$abc$estimators$1$gx_q$0 gx_q$0(
        .d(gx_q$0$d),
        .q(gx_q$0$q),
        .clock(gx_q$0$clock)
    );
    top$pipeline$abc$estimators$1$gx_q$1 gx_q$1(
        .d(gx_q$1$d),
        .q(gx_q$1$q),
        .clock(gx_q$1$clock)
    );
    top$pipeline$abc$estimators$1$gx_q$2 gx_q$2(
        .d(gx_q$2$d),
        .q(gx_q$2$q),
        .clock(gx_q$2$clock)
    );
    top$pipeline$abc$estimators$1$gx_q$3 gx_q$3(
        .d(gx_q$3$d),
        .q(gx_q$3$q),
        .clock(gx_q$3$clock)
    );
    top$pipeline$abc$estimators$1$gx_q$4 gx_q$4(
        .d(gx_q$4$d),
        .q(gx_q$4$q),
        .clock(gx_q$4$clock)
    );
    top$pipeline$abc$estimators$1$gx_q$5 gx_q$5(
        .d(gx_q$5$d),
        .q(gx_q$5$q),
        .clock(gx_q$5$clock)
    );
    top$pipeline$abc$estimators$1$gy_q$0 gy_q$0(
        .d(gy_q$0$d),
        .q(gy_q$0$q),
        .clock(gy_q$0$clock)
    );
    top$pipeline$abc$estimators$1$gy_q$1 gy_q$1(
        .d(gy_q$1$d),
        .q(gy_q$1$q),
        .clock(gy_q$1$clock)
    );
    top$pipeline$abc$estimators$1$gy_q$2 gy_q$2(
        .d(gy_q$2$d),
        .q(gy_q$2$q),
        .clock(gy_q$2$clock)
    );
    top$pipeline$abc$estimators$1$gy_q$3 gy_q$3(
        .d(gy_q$3$d),
        .q(gy_q$3$q),
        .clock(gy_q$3$clock)
    );
    top$pipeline$abc$estimators$1$gy_q$4 gy_q$4(
        .d(gy_q$4$d),
        .q(gy_q$4$q),
        .clock(gy_q$4$clock)
    );
    top$pipeline$abc$estimators$1$gy_q$5 gy_q$5(
        .d(gy_q$5$d),
        .q(gy_q$5$q),
        .clock(gy_q$5$clock)
    );
    top$pipeline$abc$estimators$1$gr_q$0 gr_q$0(
        .d(gr_q$0$d),
        .q(gr_q$0$q),
        .clock(gr_q$0$clock)
    );
    top$pipeline$abc$estimators$1$gr_q$1 gr_q$1(
        .d(gr_q$1$d),
        .q(gr_q$1$q),
        .clock(gr_q$1$clock)
    );
    top$pipeline$abc$estimators$1$gr_q$2 gr_q$2(
        .d(gr_q$2$d),
        .q(gr_q$2$q),
        .clock(gr_q$2$clock)
    );
    top$pipeline$abc$estimators$1$gr_q$3 gr_q$3(
        .d(gr_q$3$d),
        .q(gr_q$3$q),
        .clock(gr_q$3$clock)
    );
    top$pipeline$abc$estimators$1$gr_q$4 gr_q$4(
        .d(gr_q$4$d),
        .q(gr_q$4$q),
        .clock(gr_q$4$clock)
    );
    top$pipeline$abc$estimators$1$gr_q$5 gr_q$5(
        .d(gr_q$5$d),
        .q(gr_q$5$q),
        .clock(gr_q$5$clock)
    );
    top$pipeline$abc$estimators$1$dx_neg_q$0 dx_neg_q$0(
        .d(dx_neg_q$0$d),
        .q(dx_neg_q$0$q),
        .clock(dx_neg_q$0$clock)
    );
    top$pipeline$abc$estimators$1$dx_neg_q$1 dx_neg_q$1(
        .d(dx_neg_q$1$d),
        .q(dx_neg_q$1$q),
        .clock(dx_neg_q$1$clock)
    );
    top$pipeline$abc$estimators$1$dx_neg_q$2 dx_neg_q$2(
        .d(dx_neg_q$2$d),
        .q(dx_neg_q$2$q),
        .clock(dx_neg_q$2$clock)
    );
    top$pipeline$abc$estimators$1$dx_neg_q$3 dx_neg_q$3(
        .d(dx_neg_q$3$d),
        .q(dx_neg_q$3$q),
        .clock(dx_neg_q$3$clock)
    );
    top$pipeline$abc$estimators$1$dx_neg_q$4 dx_neg_q$4(
        .d(dx_neg_q$4$d),
        .q(dx_neg_q$4$q),
        .clock(dx_neg_q$4$clock)
    );
    top$pipeline$abc$estimators$1$dx_mag_q$0 dx_mag_q$0(
        .d(dx_mag_q$0$d),
        .q(dx_mag_q$0$q),
        .clock(dx_mag_q$0$clock)
    );
    top$pipeline$abc$estimators$1$dx_mag_q$1 dx_mag_q$1(
        .d(dx_mag_q$1$d),
        .q(dx_mag_q$1$q),
        .clock(dx_mag_q$1$clock)
    );
    top$pipeline$abc$estimators$1$dx_mag_q$2 dx_mag_q$2(
        .d(dx_mag_q$2$d),
        .q(dx_mag_q$2$q),
        .clock(dx_mag_q$2$clock)
    );
    top$pipeline$abc$estimators$1$dx_mag_q$3 dx_mag_q$3(
        .d(dx_mag_q$3$d),
        .q(dx_mag_q$3$q),
        .clock(dx_mag_q$3$clock)
    );
    top$pipeline$abc$estimators$1$dx_mag_q$4 dx_mag_q$4(
        .d(dx_mag_q$4$d),
        .q(dx_mag_q$4$q),
        .clock(dx_mag_q$4$clock)
    );
    top$pipeline$abc$estimators$1$dy_neg_q$0 dy_neg_q$0(
        .d(dy_neg_q$0$d),
        .q(dy_neg_q$0$q),
        .clock(dy_neg_q$0$clock)
    );
    top$pipeline$abc$estimators$1$dy_neg_q$1 dy_neg_q$1(
        .d(dy_neg_q$1$d),
        .q(dy_neg_q$1$q),
        .clock(dy_neg_q$1$clock)
    );
    top$pipeline$abc$estimators$1$dy_neg_q$2 dy_neg_q$2(
        .d(dy_neg_q$2$d),
        .q(dy_neg_q$2$q),
        .clock(dy_neg_q$2$clock)
    );
    top$pipeline$abc$estimators$1$dy_neg_q$3 dy_neg_q$3(
        .d(dy_neg_q$3$d),
        .q(dy_neg_q$3$q),
        .clock(dy_neg_q$3$clock)
    );
    top$pipeline$abc$estimators$1$dy_neg_q$4 dy_neg_q$4(
        .d(dy_neg_q$4$d),
        .q(dy_neg_q$4$q),
        .clock(dy_neg_q$4$clock)
    );
    top$pipeline$abc$estimators$1$dy_mag_q$0 dy_mag_q$0(
        .d(dy_mag_q$0$d),
        .q(dy_mag_q$0$q),
        .clock(dy_mag_q$0$clock)
    );
    top$pipeline$abc$estimators$1$dy_mag_q$1 dy_mag_q$1(
        .d(dy_mag_q$1$d),
        .q(dy_mag_q$1$q),
        .clock(dy_mag_q$1$clock)
    );
    top$pipeline$abc$estimators$1$dy_mag_q$2 dy_mag_q$2(
        .d(dy_mag_q$2$d),
        .q(dy_mag_q$2$q),
        .clock(dy_mag_q$2$clock)
    );
    top$pipeline$abc$estimators$1$dy_mag_q$3 dy_mag_q$3(
        .d(dy_mag_q$3$d),
        .q(dy_mag_q$3$q),
        .clock(dy_mag_q$3$clock)
    );
    top$pipeline$abc$estimators$1$dy_mag_q$4 dy_mag_q$4(
        .d(dy_mag_q$4$d),
        .q(dy_mag_q$4$q),
        .clock(dy_mag_q$4$clock)
    );
    top$pipeline$abc$estimators$1$px px(
        .g(px$g),
        .d_neg(px$d_neg),
        .d_mag(px$d_mag),
        .y(px$y)
    );
    top$pipeline$abc$estimators$1$py py(
        .g(py$g),
        .d_neg(py$d_neg),
        .d_mag(py$d_mag),
        .y(py$y)
    );
    top$pipeline$abc$estimators$1$px_q px_q(
        .d(px_q$d),
        .q(px_q$q),
        .clock(px_q$clock)
    );
    top$pipeline$abc$estimators$1$py_q py_q(
        .d(py_q$d),
        .q(py_q$q),
        .clock(py_q$clock)
    );
    top$pipeline$abc$estimators$1$front_top front_top(
        .clock(front_top$clock),
        .a(front_top$a),
        .b(front_top$b),
        .w(front_top$w),
        .y(front_top$y)
    );
    top$pipeline$abc$estimators$1$front_bottom front_bottom(
        .clock(front_bottom$clock),
        .a(front_bottom$a),
        .b(front_bottom$b),
        .w(front_bottom$w),
        .y(front_bottom$y)
    );
    top$pipeline$abc$estimators$1$front_y front_y(
        .clock(front_y$clock),
        .a(front_y$a),
        .b(front_y$b),
        .w(front_y$w),
        .y(front_y$y)
    );
    top$pipeline$abc$estimators$1$back_top back_top(
        .clock(back_top$clock),
        .a(back_top$a),
        .b(back_top$b),
        .w(back_top$w),
        .y(back_top$y)
    );
    top$pipeline$abc$estimators$1$back_bottom back_bottom(
        .clock(back_bottom$clock),
        .a(back_bottom$a),
        .b(back_bottom$b),
        .w(back_bottom$w),
        .y(back_bottom$y)
    );
    top$pipeline$abc$estimators$1$back_y back_y(
        .clock(back_y$clock),
        .a(back_y$a),
        .b(back_y$b),
        .w(back_y$w),
        .y(back_y$y)
    );
    top$pipeline$abc$estimators$1$sat_x sat_x(
        .v(sat_x$v),
        .y(sat_x$y)
    );
    top$pipeline$abc$estimators$1$sat_y sat_y(
        .v(sat_y$v),
        .y(sat_y$y)
    );
    top$pipeline$abc$estimators$1$sat_z sat_z(
        .v(sat_z$v),
        .y(sat_z$y)
    );
    top$pipeline$abc$estimators$1$gx_out gx_out(
        .d(gx_out$d),
        .q(gx_out$q),
        .clock(gx_out$clock)
    );
    top$pipeline$abc$estimators$1$gy_out gy_out(
        .d(gy_out$d),
        .q(gy_out$q),
        .clock(gy_out$clock)
    );
    top$pipeline$abc$estimators$1$gz_out gz_out(
        .d(gz_out$d),
        .q(gz_out$q),
        .clock(gz_out$clock)
    );
    top$pipeline$abc$estimators$1$centre_q$0 centre_q$0(
        .d(centre_q$0$d),
        .q(centre_q$0$q),
        .clock(centre_q$0$clock)
    );
    top$pipeline$abc$estimators$1$centre_q$1 centre_q$1(
        .d(centre_q$1$d),
        .q(centre_q$1$q),
        .clock(centre_q$1$clock)
    );
    top$pipeline$abc$estimators$1$centre_q$2 centre_q$2(
        .d(centre_q$2$d),
        .q(centre_q$2$q),
        .clock(centre_q$2$clock)
    );
    top$pipeline$abc$estimators$1$centre_q$3 centre_q$3(
        .d(centre_q$3$d),
        .q(centre_q$3$q),
        .clock(centre_q$3$clock)
    );
    top$pipeline$abc$estimators$1$centre_q$4 centre_q$4(
        .d(centre_q$4$d),
        .q(centre_q$4$q),
        .clock(centre_q$4$clock)
    );
    top$pipeline$abc$estimators$1$centre_q$5 centre_q$5(
        .d(centre_q$5$d),
        .q(centre_q$5$q),
        .clock(centre_q$5$clock)
    );
    top$pipeline$abc$estimators$1$centre_q$6 centre_q$6(
        .d(centre_q$6$d),
        .q(centre_q$6$q),
        .clock(centre_q$6$clock)
    );
    
    // Update code
    always @(*) begin
        px_q$clock = clock;
        py_q$clock = clock;
        gx_out$clock = clock;
        gy_out$clock = clock;
        gz_out$clock = clock;
        px_q$d = px_q$q;
        py_q$d = py_q$q;
        gx_out$d = gx_out$q;
        gy_out$d = gy_out$q;
        gz_out$d = gz_out$q;
        centre_q$0$clock = clock;
        centre_q$1$clock = clock;
        centre_q$2$clock = clock;
        centre_q$3$clock = clock;
        centre_q$4$clock = clock;
        centre_q$5$clock = clock;
        centre_q$6$clock = clock;
        centre_q$0$d = centre;
        centre_q$1$d = centre_q$0$q;
        centre_q$2$d = centre_q$1$q;
        centre_q$3$d = centre_q$2$q;
        centre_q$4$d = centre_q$3$q;
        centre_q$5$d = centre_q$4$q;
        centre_q$6$d = centre_q$5$q;
        sample = centre_q$6$q;
        gx_q$0$clock = clock;
        gy_q$0$clock = clock;
        gr_q$0$clock = clock;
        gx_q$1$clock = clock;
        gy_q$1$clock = clock;
        gr_q$1$clock = clock;
        gx_q$2$clock = clock;
        gy_q$2$clock = clock;
        gr_q$2$clock = clock;
        gx_q$3$clock = clock;
        gy_q$3$clock = clock;
        gr_q$3$clock = clock;
        gx_q$4$clock = clock;
        gy_q$4$clock = clock;
        gr_q$4$clock = clock;
        gx_q$5$clock = clock;
        gy_q$5$clock = clock;
        gr_q$5$clock = clock;
        b10x_q$0$clock = clock;
        b10y_q$0$clock = clock;
        b10z_q$0$clock = clock;
        b10x_q$1$clock = clock;
        b10y_q$1$clock = clock;
        b10z_q$1$clock = clock;
        dx_neg_q$0$clock = clock;
        dx_mag_q$0$clock = clock;
        dy_neg_q$0$clock = clock;
        dy_mag_q$0$clock = clock;
        dx_neg_q$1$clock = clock;
        dx_mag_q$1$clock = clock;
        dy_neg_q$1$clock = clock;
        dy_mag_q$1$clock = clock;
        dx_neg_q$2$clock = clock;
        dx_mag_q$2$clock = clock;
        dy_neg_q$2$clock = clock;
        dy_mag_q$2$clock = clock;
        dx_neg_q$3$clock = clock;
        dx_mag_q$3$clock = clock;
        dy_neg_q$3$clock = clock;
        dy_mag_q$3$clock = clock;
        dx_neg_q$4$clock = clock;
        dx_mag_q$4$clock = clock;
        dy_neg_q$4$clock = clock;
        dy_mag_q$4$clock = clock;
        front_top$clock = clock;
        front_bottom$clock = clock;
        front_y$clock = clock;
        back_top$clock = clock;
        back_bottom$clock = clock;
        back_y$clock = clock;
        gx_q$0$d = xp - xm;
        gy_q$0$d = yp - ym;
        gr_q$0$d = kp4 - km4;
        gx_q$1$d = gx_q$0$q;
        gy_q$1$d = gy_q$0$q;
        gr_q$1$d = gr_q$0$q;
        gx_q$2$d = gx_q$1$q;
        gy_q$2$d = gy_q$1$q;
        gr_q$2$d = gr_q$1$q;
        gx_q$3$d = gx_q$2$q;
        gy_q$3$d = gy_q$2$q;
        gr_q$3$d = gr_q$2$q;
        gx_q$4$d = gx_q$3$q;
        gy_q$4$d = gy_q$3$q;
        gr_q$4$d = gr_q$3$q;
        gx_q$5$d = gx_q$4$q;
        gy_q$5$d = gy_q$4$q;
        gr_q$5$d = gr_q$4$q;
        sums26$clock = clock;
        sums26$xp = xp;
        sums26$xm = xm;
        sums26$yp = yp;
        sums26$ym = ym;
        sums26$c0 = c0;
        sums26$c2 = c2;
        sums26$c6 = c6;
        sums26$c8 = c8;
        sums26$kp0 = kp0;
        sums26$kp1 = kp1;
        sums26$kp2 = kp2;
        sums26$kp3 = kp3;
        sums26$kp4 = kp4;
        sums26$kp5 = kp5;
        sums26$kp6 = kp6;
        sums26$kp7 = kp7;
        sums26$kp8 = kp8;
        sums26$km0 = km0;
        sums26$km1 = km1;
        sums26$km2 = km2;
        sums26$km3 = km3;
        sums26$km4 = km4;
        sums26$km5 = km5;
        sums26$km6 = km6;
        sums26$km7 = km7;
        sums26$km8 = km8;
        basis10$clock = clock;
        basis10$xp = xp;
        basis10$xm = xm;
        basis10$yp = yp;
        basis10$ym = ym;
        basis10$kp1 = kp1;
        basis10$kp3 = kp3;
        basis10$kp4 = kp4;
        basis10$kp5 = kp5;
        basis10$kp7 = kp7;
        basis10$km1 = km1;
        basis10$km3 = km3;
        basis10$km4 = km4;
        basis10$km5 = km5;
        basis10$km7 = km7;
        basis10$dx_neg = dx_neg;
        basis10$dx_mag = dx_mag;
        basis10$dy_neg = dy_neg;
        basis10$dy_mag = dy_mag;
        basis10$weights = weights10;
        basis10$basis_x = basis10_x;
        basis10$basis_y = basis10_y;
        basis10$basis_z = basis10_z;
        if (n26) begin
            gx_q$2$d = sums26$gx;
            gy_q$2$d = sums26$gy;
            gr_q$2$d = sums26$gr;
        end
        dx_neg_q$0$d = dx_neg;
        dx_mag_q$0$d = dx_mag;
        dy_neg_q$0$d = dy_neg;
        dy_mag_q$0$d = dy_mag;
        dx_neg_q$1$d = dx_neg_q$0$q;
        dx_mag_q$1$d = dx_mag_q$0$q;
        dy_neg_q$1$d = dy_neg_q$0$q;
        dy_mag_q$1$d = dy_mag_q$0$q;
        dx_neg_q$2$d = dx_neg_q$1$q;
        dx_mag_q$2$d = dx_mag_q$1$q;
        dy_neg_q$2$d = dy_neg_q$1$q;
        dy_mag_q$2$d = dy_mag_q$1$q;
        dx_neg_q$3$d = dx_neg_q$2$q;
        dx_mag_q$3$d = dx_mag_q$2$q;
        dy_neg_q$3$d = dy_neg_q$2$q;
        dy_mag_q$3$d = dy_mag_q$2$q;
        dx_neg_q$4$d = dx_neg_q$3$q;
        dx_mag_q$4$d = dx_mag_q$3$q;
        dy_neg_q$4$d = dy_neg_q$3$q;
        dy_mag_q$4$d = dy_mag_q$3$q;
        px$g = gx_q$4$q;
        px$d_neg = dx_neg_q$4$q;
        px$d_mag = dx_mag_q$4$q;
        py$g = gy_q$4$q;
        py$d_neg = dy_neg_q$4$q;
        py$d_mag = dy_mag_q$4$q;
        px_q$d = px$y;
        py_q$d = py$y;
        shear_sum = px_q$q + py_q$q + half;
        shear = shear_sum >> shift;
        if (shear_sum['h3f]) begin
            shear = ~((~shear_sum) >> shift);
        end
        sx_pos = ~dx_neg & |dx_mag;
        sx_neg = dx_neg & |dx_mag;
        sy_pos = ~dy_neg & |dy_mag;
        sy_neg = dy_neg & |dy_mag;
        front_row$0 = kp3;
        back_row$0 = km3;
        if (sy_pos) begin
            front_row$0 = kp6;
            back_row$0 = km0;
        end
        if (sy_neg) begin
            front_row$0 = kp0;
            back_row$0 = km6;
        end
        front_row$1 = kp4;
        back_row$1 = km4;
        if (sy_pos) begin
            front_row$1 = kp7;
            back_row$1 = km1;
        end
        if (sy_neg) begin
            front_row$1 = kp1;
            back_row$1 = km7;
        end
        front_row$2 = kp5;
        back_row$2 = km5;
        if (sy_pos) begin
            front_row$2 = kp8;
            back_row$2 = km2;
        end
        if (sy_neg) begin
            front_row$2 = kp2;
            back_row$2 = km8;
        end
        front_x = kp4;
        front_xy = front_row$1;
        back_x = km4;
        back_xy = back_row$1;
        if (sx_pos) begin
            front_x = kp5;
            front_xy = front_row$2;
            back_x = km3;
            back_xy = back_row$0;
        end
        if (sx_neg) begin
            front_x = kp3;
            front_xy = front_row$0;
            back_x = km5;
            back_xy = back_row$2;
        end
        front_top$a = kp4;
        front_top$b = front_x;
        front_top$w = dx_mag;
        front_bottom$a = front_row$1;
        front_bottom$b = front_xy;
        front_bottom$w = dx_mag;
        front_y$a = front_top$y;
        front_y$b = front_bottom$y;
        front_y$w = dy_mag_q$2$q;
        back_top$a = km4;
        back_top$b = back_x;
        back_top$w = dx_mag;
        back_bottom$a = back_row$1;
        back_bottom$b = back_xy;
        back_bottom$w = dx_mag;
        back_y$a = back_top$y;
        back_y$b = back_bottom$y;
        back_y$w = dy_mag_q$2$q;
        gr_wide = 64'(gr_q$5$q);
        if (gr_q$5$q['h1f]) begin
            gr_wide = 64'(gr_q$5$q) | sign_ext;
        end
        gz_wide = gr_wide - shear;
        if (n12) begin
            gz_wide = 64'(front_y$y) - 64'(back_y$y);
        end
        sat_x$v = 64'(gx_q$5$q);
        if (gx_q$5$q['h1f]) begin
            sat_x$v = 64'(gx_q$5$q) | sign_ext;
        end
        sat_y$v = 64'(gy_q$5$q);
        if (gy_q$5$q['h1f]) begin
            sat_y$v = 64'(gy_q$5$q) | sign_ext;
        end
        sat_z$v = gz_wide;
        b10x_q$0$d = basis10$gx;
        b10y_q$0$d = basis10$gy;
        b10z_q$0$d = basis10$gz;
        b10x_q$1$d = b10x_q$0$q;
        b10y_q$1$d = b10y_q$0$q;
        b10z_q$1$d = b10z_q$0$q;
        if (n10) begin
            sat_x$v = b10x_q$1$q;
            sat_y$v = b10y_q$1$q;
            sat_z$v = b10z_q$1$q;
        end
        gx_out$d = sat_x$y;
        gy_out$d = sat_y$y;
        gz_out$d = sat_z$y;
        gx = gx_out$q;
        gy = gy_out$q;
        gz = gz_out$q;
    end
    
endmodule // top$pipeline$abc$estimators$1
module top$pipeline$abc$estimators$1$b10x_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$b10x_q$0
module top$pipeline$abc$estimators$1$b10x_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$b10x_q$1
module top$pipeline$abc$estimators$1$b10y_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$b10y_q$0
module top$pipeline$abc$estimators$1$b10y_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$b10y_q$1
module top$pipeline$abc$estimators$1$b10z_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$b10z_q$0
module top$pipeline$abc$estimators$1$b10z_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$b10z_q$1
module top$pipeline$abc$estimators$1$back_bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$1$back_bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$1$back_bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$1$back_bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$1$back_bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$1$back_bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$1$back_bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$1$back_bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$1$back_bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$1$back_bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$1$back_bottom
module top$pipeline$abc$estimators$1$back_bottom$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_bottom$a_q
module top$pipeline$abc$estimators$1$back_bottom$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_bottom$a_q2
module top$pipeline$abc$estimators$1$back_bottom$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_bottom$diff_q
module top$pipeline$abc$estimators$1$back_bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$1$back_bottom$narrow
module top$pipeline$abc$estimators$1$back_bottom$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_bottom$prod_q
module top$pipeline$abc$estimators$1$back_bottom$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_bottom$up_q
module top$pipeline$abc$estimators$1$back_bottom$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_bottom$up_q2
module top$pipeline$abc$estimators$1$back_bottom$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_bottom$w_q
module top$pipeline$abc$estimators$1$back_bottom$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_bottom$y_q
module top$pipeline$abc$estimators$1$back_top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$1$back_top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$1$back_top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$1$back_top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$1$back_top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$1$back_top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$1$back_top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$1$back_top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$1$back_top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$1$back_top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$1$back_top
module top$pipeline$abc$estimators$1$back_top$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_top$a_q
module top$pipeline$abc$estimators$1$back_top$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_top$a_q2
module top$pipeline$abc$estimators$1$back_top$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_top$diff_q
module top$pipeline$abc$estimators$1$back_top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$1$back_top$narrow
module top$pipeline$abc$estimators$1$back_top$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_top$prod_q
module top$pipeline$abc$estimators$1$back_top$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_top$up_q
module top$pipeline$abc$estimators$1$back_top$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_top$up_q2
module top$pipeline$abc$estimators$1$back_top$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_top$w_q
module top$pipeline$abc$estimators$1$back_top$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_top$y_q
module top$pipeline$abc$estimators$1$back_y(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$1$back_y$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$1$back_y$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$1$back_y$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$1$back_y$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$1$back_y$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$1$back_y$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$1$back_y$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$1$back_y$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$1$back_y$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$1$back_y
module top$pipeline$abc$estimators$1$back_y$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_y$a_q
module top$pipeline$abc$estimators$1$back_y$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_y$a_q2
module top$pipeline$abc$estimators$1$back_y$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_y$diff_q
module top$pipeline$abc$estimators$1$back_y$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$1$back_y$narrow
module top$pipeline$abc$estimators$1$back_y$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_y$prod_q
module top$pipeline$abc$estimators$1$back_y$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_y$up_q
module top$pipeline$abc$estimators$1$back_y$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_y$up_q2
module top$pipeline$abc$estimators$1$back_y$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_y$w_q
module top$pipeline$abc$estimators$1$back_y$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$back_y$y_q
module top$pipeline$abc$estimators$1$centre_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$centre_q$0
module top$pipeline$abc$estimators$1$centre_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$centre_q$1
module top$pipeline$abc$estimators$1$centre_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$centre_q$2
module top$pipeline$abc$estimators$1$centre_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$centre_q$3
module top$pipeline$abc$estimators$1$centre_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$centre_q$4
module top$pipeline$abc$estimators$1$centre_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$centre_q$5
module top$pipeline$abc$estimators$1$centre_q$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$centre_q$6
module top$pipeline$abc$estimators$1$dx_mag_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dx_mag_q$0
module top$pipeline$abc$estimators$1$dx_mag_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dx_mag_q$1
module top$pipeline$abc$estimators$1$dx_mag_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dx_mag_q$2
module top$pipeline$abc$estimators$1$dx_mag_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dx_mag_q$3
module top$pipeline$abc$estimators$1$dx_mag_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dx_mag_q$4
module top$pipeline$abc$estimators$1$dx_neg_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dx_neg_q$0
module top$pipeline$abc$estimators$1$dx_neg_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dx_neg_q$1
module top$pipeline$abc$estimators$1$dx_neg_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dx_neg_q$2
module top$pipeline$abc$estimators$1$dx_neg_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dx_neg_q$3
module top$pipeline$abc$estimators$1$dx_neg_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dx_neg_q$4
module top$pipeline$abc$estimators$1$dy_mag_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dy_mag_q$0
module top$pipeline$abc$estimators$1$dy_mag_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dy_mag_q$1
module top$pipeline$abc$estimators$1$dy_mag_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dy_mag_q$2
module top$pipeline$abc$estimators$1$dy_mag_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dy_mag_q$3
module top$pipeline$abc$estimators$1$dy_mag_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dy_mag_q$4
module top$pipeline$abc$estimators$1$dy_neg_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dy_neg_q$0
module top$pipeline$abc$estimators$1$dy_neg_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dy_neg_q$1
module top$pipeline$abc$estimators$1$dy_neg_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dy_neg_q$2
module top$pipeline$abc$estimators$1$dy_neg_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dy_neg_q$3
module top$pipeline$abc$estimators$1$dy_neg_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$dy_neg_q$4
module top$pipeline$abc$estimators$1$front_bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$1$front_bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$1$front_bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$1$front_bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$1$front_bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$1$front_bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$1$front_bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$1$front_bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$1$front_bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$1$front_bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$1$front_bottom
module top$pipeline$abc$estimators$1$front_bottom$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_bottom$a_q
module top$pipeline$abc$estimators$1$front_bottom$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_bottom$a_q2
module top$pipeline$abc$estimators$1$front_bottom$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_bottom$diff_q
module top$pipeline$abc$estimators$1$front_bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$1$front_bottom$narrow
module top$pipeline$abc$estimators$1$front_bottom$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_bottom$prod_q
module top$pipeline$abc$estimators$1$front_bottom$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_bottom$up_q
module top$pipeline$abc$estimators$1$front_bottom$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_bottom$up_q2
module top$pipeline$abc$estimators$1$front_bottom$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_bottom$w_q
module top$pipeline$abc$estimators$1$front_bottom$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_bottom$y_q
module top$pipeline$abc$estimators$1$front_top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$1$front_top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$1$front_top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$1$front_top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$1$front_top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$1$front_top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$1$front_top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$1$front_top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$1$front_top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$1$front_top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$1$front_top
module top$pipeline$abc$estimators$1$front_top$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_top$a_q
module top$pipeline$abc$estimators$1$front_top$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_top$a_q2
module top$pipeline$abc$estimators$1$front_top$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_top$diff_q
module top$pipeline$abc$estimators$1$front_top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$1$front_top$narrow
module top$pipeline$abc$estimators$1$front_top$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_top$prod_q
module top$pipeline$abc$estimators$1$front_top$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_top$up_q
module top$pipeline$abc$estimators$1$front_top$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_top$up_q2
module top$pipeline$abc$estimators$1$front_top$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_top$w_q
module top$pipeline$abc$estimators$1$front_top$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_top$y_q
module top$pipeline$abc$estimators$1$front_y(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$1$front_y$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$1$front_y$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$1$front_y$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$1$front_y$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$1$front_y$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$1$front_y$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$1$front_y$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$1$front_y$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$1$front_y$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$1$front_y
module top$pipeline$abc$estimators$1$front_y$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_y$a_q
module top$pipeline$abc$estimators$1$front_y$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_y$a_q2
module top$pipeline$abc$estimators$1$front_y$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_y$diff_q
module top$pipeline$abc$estimators$1$front_y$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$1$front_y$narrow
module top$pipeline$abc$estimators$1$front_y$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_y$prod_q
module top$pipeline$abc$estimators$1$front_y$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_y$up_q
module top$pipeline$abc$estimators$1$front_y$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_y$up_q2
module top$pipeline$abc$estimators$1$front_y$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_y$w_q
module top$pipeline$abc$estimators$1$front_y$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$front_y$y_q
module top$pipeline$abc$estimators$1$gr_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gr_q$0
module top$pipeline$abc$estimators$1$gr_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gr_q$1
module top$pipeline$abc$estimators$1$gr_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gr_q$2
module top$pipeline$abc$estimators$1$gr_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gr_q$3
module top$pipeline$abc$estimators$1$gr_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gr_q$4
module top$pipeline$abc$estimators$1$gr_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gr_q$5
module top$pipeline$abc$estimators$1$gx_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gx_out
module top$pipeline$abc$estimators$1$gx_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gx_q$0
module top$pipeline$abc$estimators$1$gx_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gx_q$1
module top$pipeline$abc$estimators$1$gx_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gx_q$2
module top$pipeline$abc$estimators$1$gx_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gx_q$3
module top$pipeline$abc$estimators$1$gx_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gx_q$4
module top$pipeline$abc$estimators$1$gx_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gx_q$5
module top$pipeline$abc$estimators$1$gy_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gy_out
module top$pipeline$abc$estimators$1$gy_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gy_q$0
module top$pipeline$abc$estimators$1$gy_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gy_q$1
module top$pipeline$abc$estimators$1$gy_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gy_q$2
module top$pipeline$abc$estimators$1$gy_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gy_q$3
module top$pipeline$abc$estimators$1$gy_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gy_q$4
module top$pipeline$abc$estimators$1$gy_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gy_q$5
module top$pipeline$abc$estimators$1$gz_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$gz_out
module top$pipeline$abc$estimators$1$px(g,d_neg,d_mag,y);
    
    // Module arguments
    input wire  [31:0] g;
    input wire  d_neg;
    input wire  [15:0] d_mag;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] mag;
    reg  [63:0] prod;
    
    // Update code
    reg  [63:0] y_pass;
    always @(*) begin
        mag = g;
        if (g['h1f]) begin
            mag = ~g + 'h1;
        end
        prod = 64'(mag[('h0)+:(16)] * d_mag);
        if (wide) begin
            prod = (64'(mag[('h10)+:(16)] * d_mag) << 'h10) + 64'(mag[('h0)+:(16)] * d_mag);
        end
        y_pass = prod;
        if (g['h1f] ^ d_neg) begin
            y_pass = ~prod + 'h1;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$1$px
module top$pipeline$abc$estimators$1$px_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$px_q
module top$pipeline$abc$estimators$1$py(g,d_neg,d_mag,y);
    
    // Module arguments
    input wire  [31:0] g;
    input wire  d_neg;
    input wire  [15:0] d_mag;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] mag;
    reg  [63:0] prod;
    
    // Update code
    reg  [63:0] y_pass;
    always @(*) begin
        mag = g;
        if (g['h1f]) begin
            mag = ~g + 'h1;
        end
        prod = 64'(mag[('h0)+:(16)] * d_mag);
        if (wide) begin
            prod = (64'(mag[('h10)+:(16)] * d_mag) << 'h10) + 64'(mag[('h0)+:(16)] * d_mag);
        end
        y_pass = prod;
        if (g['h1f] ^ d_neg) begin
            y_pass = ~prod + 'h1;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$1$py
module top$pipeline$abc$estimators$1$py_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$1$py_q
module top$pipeline$abc$estimators$1$sat_x(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$1$sat_x
module top$pipeline$abc$estimators$1$sat_y(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$1$sat_y
module top$pipeline$abc$estimators$1$sat_z(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$1$sat_z
module top$pipeline$abc$estimators$2(clock,xp,xm,yp,ym,kp0,kp1,kp2,kp3,kp4,kp5,kp6,kp7,kp8,km0,km1,km2,km3,km4,km5,km6,km7,km8,c0,c2,c6,c8,weights10,basis10_x,basis10_y,basis10_z,dx_neg,dx_mag,dy_neg,dy_mag,centre,sample,gx,gy,gz);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] xp;
    input wire  [31:0] xm;
    input wire  [31:0] yp;
    input wire  [31:0] ym;
    input wire  [31:0] kp0;
    input wire  [31:0] kp1;
    input wire  [31:0] kp2;
    input wire  [31:0] kp3;
    input wire  [31:0] kp4;
    input wire  [31:0] kp5;
    input wire  [31:0] kp6;
    input wire  [31:0] kp7;
    input wire  [31:0] kp8;
    input wire  [31:0] km0;
    input wire  [31:0] km1;
    input wire  [31:0] km2;
    input wire  [31:0] km3;
    input wire  [31:0] km4;
    input wire  [31:0] km5;
    input wire  [31:0] km6;
    input wire  [31:0] km7;
    input wire  [31:0] km8;
    input wire  [31:0] c0;
    input wire  [31:0] c2;
    input wire  [31:0] c6;
    input wire  [31:0] c8;
    input wire  [63:0] weights10;
    input wire  [63:0] basis10_x;
    input wire  [63:0] basis10_y;
    input wire  [63:0] basis10_z;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [31:0] centre;
    output reg  [31:0] sample;
    output reg  [31:0] gx;
    output reg  [31:0] gy;
    output reg  [31:0] gz;
    
    // Constant declarations
    localparam  n12 = 1'b1;
    localparam  n26 = 1'b0;
    localparam  n10 = 1'b0;
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  sign_ext = 64'hffffffff00000000;
    
    // Stub signals
    reg  sums26$clock;
    reg  [31:0] sums26$xp;
    reg  [31:0] sums26$xm;
    reg  [31:0] sums26$yp;
    reg  [31:0] sums26$ym;
    reg  [31:0] sums26$c0;
    reg  [31:0] sums26$c2;
    reg  [31:0] sums26$c6;
    reg  [31:0] sums26$c8;
    reg  [31:0] sums26$kp0;
    reg  [31:0] sums26$kp1;
    reg  [31:0] sums26$kp2;
    reg  [31:0] sums26$kp3;
    reg  [31:0] sums26$kp4;
    reg  [31:0] sums26$kp5;
    reg  [31:0] sums26$kp6;
    reg  [31:0] sums26$kp7;
    reg  [31:0] sums26$kp8;
    reg  [31:0] sums26$km0;
    reg  [31:0] sums26$km1;
    reg  [31:0] sums26$km2;
    reg  [31:0] sums26$km3;
    reg  [31:0] sums26$km4;
    reg  [31:0] sums26$km5;
    reg  [31:0] sums26$km6;
    reg  [31:0] sums26$km7;
    reg  [31:0] sums26$km8;
    wire  [31:0] sums26$gx = 'h0;
    wire  [31:0] sums26$gy = 'h0;
    wire  [31:0] sums26$gr = 'h0;
    reg  basis10$clock;
    reg  [31:0] basis10$xp;
    reg  [31:0] basis10$xm;
    reg  [31:0] basis10$yp;
    reg  [31:0] basis10$ym;
    reg  [31:0] basis10$kp1;
    reg  [31:0] basis10$kp3;
    reg  [31:0] basis10$kp4;
    reg  [31:0] basis10$kp5;
    reg  [31:0] basis10$kp7;
    reg  [31:0] basis10$km1;
    reg  [31:0] basis10$km3;
    reg  [31:0] basis10$km4;
    reg  [31:0] basis10$km5;
    reg  [31:0] basis10$km7;
    reg  basis10$dx_neg;
    reg  [15:0] basis10$dx_mag;
    reg  basis10$dy_neg;
    reg  [15:0] basis10$dy_mag;
    reg  [63:0] basis10$weights;
    reg  [63:0] basis10$basis_x;
    reg  [63:0] basis10$basis_y;
    reg  [63:0] basis10$basis_z;
    wire  [63:0] basis10$gx = 'h0;
    wire  [63:0] basis10$gy = 'h0;
    wire  [63:0] basis10$gz = 'h0;
    reg  [63:0] b10x_q$0$d;
    wire  [63:0] b10x_q$0$q;
    reg  b10x_q$0$clock;
    reg  [63:0] b10x_q$1$d;
    wire  [63:0] b10x_q$1$q;
    reg  b10x_q$1$clock;
    reg  [63:0] b10y_q$0$d;
    wire  [63:0] b10y_q$0$q;
    reg  b10y_q$0$clock;
    reg  [63:0] b10y_q$1$d;
    wire  [63:0] b10y_q$1$q;
    reg  b10y_q$1$clock;
    reg  [63:0] b10z_q$0$d;
    wire  [63:0] b10z_q$0$q;
    reg  b10z_q$0$clock;
    reg  [63:0] b10z_q$1$d;
    wire  [63:0] b10z_q$1$q;
    reg  b10z_q$1$clock;
    reg  [31:0] gx_q$0$d;
    wire  [31:0] gx_q$0$q;
    reg  gx_q$0$clock;
    reg  [31:0] gx_q$1$d;
    wire  [31:0] gx_q$1$q;
    reg  gx_q$1$clock;
    reg  [31:0] gx_q$2$d;
    wire  [31:0] gx_q$2$q;
    reg  gx_q$2$clock;
    reg  [31:0] gx_q$3$d;
    wire  [31:0] gx_q$3$q;
    reg  gx_q$3$clock;
    reg  [31:0] gx_q$4$d;
    wire  [31:0] gx_q$4$q;
    reg  gx_q$4$clock;
    reg  [31:0] gx_q$5$d;
    wire  [31:0] gx_q$5$q;
    reg  gx_q$5$clock;
    reg  [31:0] gy_q$0$d;
    wire  [31:0] gy_q$0$q;
    reg  gy_q$0$clock;
    reg  [31:0] gy_q$1$d;
    wire  [31:0] gy_q$1$q;
    reg  gy_q$1$clock;
    reg  [31:0] gy_q$2$d;
    wire  [31:0] gy_q$2$q;
    reg  gy_q$2$clock;
    reg  [31:0] gy_q$3$d;
    wire  [31:0] gy_q$3$q;
    reg  gy_q$3$clock;
    reg  [31:0] gy_q$4$d;
    wire  [31:0] gy_q$4$q;
    reg  gy_q$4$clock;
    reg  [31:0] gy_q$5$d;
    wire  [31:0] gy_q$5$q;
    reg  gy_q$5$clock;
    reg  [31:0] gr_q$0$d;
    wire  [31:0] gr_q$0$q;
    reg  gr_q$0$clock;
    reg  [31:0] gr_q$1$d;
    wire  [31:0] gr_q$1$q;
    reg  gr_q$1$clock;
    reg  [31:0] gr_q$2$d;
    wire  [31:0] gr_q$2$q;
    reg  gr_q$2$clock;
    reg  [31:0] gr_q$3$d;
    wire  [31:0] gr_q$3$q;
    reg  gr_q$3$clock;
    reg  [31:0] gr_q$4$d;
    wire  [31:0] gr_q$4$q;
    reg  gr_q$4$clock;
    reg  [31:0] gr_q$5$d;
    wire  [31:0] gr_q$5$q;
    reg  gr_q$5$clock;
    reg  dx_neg_q$0$d;
    wire  dx_neg_q$0$q;
    reg  dx_neg_q$0$clock;
    reg  dx_neg_q$1$d;
    wire  dx_neg_q$1$q;
    reg  dx_neg_q$1$clock;
    reg  dx_neg_q$2$d;
    wire  dx_neg_q$2$q;
    reg  dx_neg_q$2$clock;
    reg  dx_neg_q$3$d;
    wire  dx_neg_q$3$q;
    reg  dx_neg_q$3$clock;
    reg  dx_neg_q$4$d;
    wire  dx_neg_q$4$q;
    reg  dx_neg_q$4$clock;
    reg  [15:0] dx_mag_q$0$d;
    wire  [15:0] dx_mag_q$0$q;
    reg  dx_mag_q$0$clock;
    reg  [15:0] dx_mag_q$1$d;
    wire  [15:0] dx_mag_q$1$q;
    reg  dx_mag_q$1$clock;
    reg  [15:0] dx_mag_q$2$d;
    wire  [15:0] dx_mag_q$2$q;
    reg  dx_mag_q$2$clock;
    reg  [15:0] dx_mag_q$3$d;
    wire  [15:0] dx_mag_q$3$q;
    reg  dx_mag_q$3$clock;
    reg  [15:0] dx_mag_q$4$d;
    wire  [15:0] dx_mag_q$4$q;
    reg  dx_mag_q$4$clock;
    reg  dy_neg_q$0$d;
    wire  dy_neg_q$0$q;
    reg  dy_neg_q$0$clock;
    reg  dy_neg_q$1$d;
    wire  dy_neg_q$1$q;
    reg  dy_neg_q$1$clock;
    reg  dy_neg_q$2$d;
    wire  dy_neg_q$2$q;
    reg  dy_neg_q$2$clock;
    reg  dy_neg_q$3$d;
    wire  dy_neg_q$3$q;
    reg  dy_neg_q$3$clock;
    reg  dy_neg_q$4$d;
    wire  dy_neg_q$4$q;
    reg  dy_neg_q$4$clock;
    reg  [15:0] dy_mag_q$0$d;
    wire  [15:0] dy_mag_q$0$q;
    reg  dy_mag_q$0$clock;
    reg  [15:0] dy_mag_q$1$d;
    wire  [15:0] dy_mag_q$1$q;
    reg  dy_mag_q$1$clock;
    reg  [15:0] dy_mag_q$2$d;
    wire  [15:0] dy_mag_q$2$q;
    reg  dy_mag_q$2$clock;
    reg  [15:0] dy_mag_q$3$d;
    wire  [15:0] dy_mag_q$3$q;
    reg  dy_mag_q$3$clock;
    reg  [15:0] dy_mag_q$4$d;
    wire  [15:0] dy_mag_q$4$q;
    reg  dy_mag_q$4$clock;
    reg  [31:0] px$g;
    reg  px$d_neg;
    reg  [15:0] px$d_mag;
    wire  [63:0] px$y;
    reg  [31:0] py$g;
    reg  py$d_neg;
    reg  [15:0] py$d_mag;
    wire  [63:0] py$y;
    reg  [63:0] px_q$d;
    wire  [63:0] px_q$q;
    reg  px_q$clock;
    reg  [63:0] py_q$d;
    wire  [63:0] py_q$q;
    reg  py_q$clock;
    reg  front_top$clock;
    reg  [31:0] front_top$a;
    reg  [31:0] front_top$b;
    reg  [15:0] front_top$w;
    wire  [31:0] front_top$y;
    reg  front_bottom$clock;
    reg  [31:0] front_bottom$a;
    reg  [31:0] front_bottom$b;
    reg  [15:0] front_bottom$w;
    wire  [31:0] front_bottom$y;
    reg  front_y$clock;
    reg  [31:0] front_y$a;
    reg  [31:0] front_y$b;
    reg  [15:0] front_y$w;
    wire  [31:0] front_y$y;
    reg  back_top$clock;
    reg  [31:0] back_top$a;
    reg  [31:0] back_top$b;
    reg  [15:0] back_top$w;
    wire  [31:0] back_top$y;
    reg  back_bottom$clock;
    reg  [31:0] back_bottom$a;
    reg  [31:0] back_bottom$b;
    reg  [15:0] back_bottom$w;
    wire  [31:0] back_bottom$y;
    reg  back_y$clock;
    reg  [31:0] back_y$a;
    reg  [31:0] back_y$b;
    reg  [15:0] back_y$w;
    wire  [31:0] back_y$y;
    reg  [63:0] sat_x$v;
    wire  [31:0] sat_x$y;
    reg  [63:0] sat_y$v;
    wire  [31:0] sat_y$y;
    reg  [63:0] sat_z$v;
    wire  [31:0] sat_z$y;
    reg  [31:0] gx_out$d;
    wire  [31:0] gx_out$q;
    reg  gx_out$clock;
    reg  [31:0] gy_out$d;
    wire  [31:0] gy_out$q;
    reg  gy_out$clock;
    reg  [31:0] gz_out$d;
    wire  [31:0] gz_out$q;
    reg  gz_out$clock;
    reg  [31:0] centre_q$0$d;
    wire  [31:0] centre_q$0$q;
    reg  centre_q$0$clock;
    reg  [31:0] centre_q$1$d;
    wire  [31:0] centre_q$1$q;
    reg  centre_q$1$clock;
    reg  [31:0] centre_q$2$d;
    wire  [31:0] centre_q$2$q;
    reg  centre_q$2$clock;
    reg  [31:0] centre_q$3$d;
    wire  [31:0] centre_q$3$q;
    reg  centre_q$3$clock;
    reg  [31:0] centre_q$4$d;
    wire  [31:0] centre_q$4$q;
    reg  centre_q$4$clock;
    reg  [31:0] centre_q$5$d;
    wire  [31:0] centre_q$5$q;
    reg  centre_q$5$clock;
    reg  [31:0] centre_q$6$d;
    wire  [31:0] centre_q$6$q;
    reg  centre_q$6$clock;
    
    // Local signals
    reg  [63:0] shear_sum;
    reg  [63:0] shear;
    reg  sx_pos;
    reg  sx_neg;
    reg  sy_pos;
    reg  sy_neg;
    reg  [31:0] front_row$0;
    reg  [31:0] front_row$1;
    reg  [31:0] front_row$2;
    reg  [31:0] back_row$0;
    reg  [31:0] back_row$1;
    reg  [31:0] back_row$2;
    reg  [31:0] front_x;
    reg  [31:0] front_xy;
    reg  [31:0] back_x;
    reg  [31:0] back_xy;
    reg  [63:0] gr_wide;
    reg  [63:0] gz_wide;
    
    // Sub module instances
    top$pipeline$abc$estimators$2$b10x_q$0 b10x_q$0(
        .d(b10x_q$0$d),
        .q(b10x_q$0$q),
        .clock(b10x_q$0$clock)
    );
    top$pipeline$abc$estimators$2$b10x_q$1 b10x_q$1(
        .d(b10x_q$1$d),
        .q(b10x_q$1$q),
        .clock(b10x_q$1$clock)
    );
    top$pipeline$abc$estimators$2$b10y_q$0 b10y_q$0(
        .d(b10y_q$0$d),
        .q(b10y_q$0$q),
        .clock(b10y_q$0$clock)
    );
    top$pipeline$abc$estimators$2$b10y_q$1 b10y_q$1(
        .d(b10y_q$1$d),
        .q(b10y_q$1$q),
        .clock(b10y_q$1$clock)
    );
    top$pipeline$abc$estimators$2$b10z_q$0 b10z_q$0(
        .d(b10z_q$0$d),
        .q(b10z_q$0$q),
        .clock(b10z_q$0$clock)
    );
    top$pipeline$abc$estimators$2$b10z_q$1 b10z_q$1(
        .d(b10z_q$1$d),
        .q(b10z_q$1$q),
        .clock(b10z_q$1$clock)
    );
    top$pipeline$abc$estimators$2$gx_q$0 gx_q$0(
        .d(gx_q$0$d),
        .q(gx_q$0$q),
        .clock(gx_q$0$clock)
    );
    top$pipeline$abc$estimators$2$gx_q$1 gx_q$1(
        .d(gx_q$1$d),
        .q(gx_q$1$q),
        .clock(gx_q$1$clock)
    );
    top$pipeline$abc$estimators$2$gx_q$2 gx_q$2(
        .d(gx_q$2$d),
        .q(gx_q$2$q),
        .clock(gx_q$2$clock)
    );
    top$pipeline$abc$estimators$2$gx_q$3 gx_q$3(
        .d(gx_q$3$d),
        .q(gx_q$3$q),
        .clock(gx_q$3$clock)
    );
    top$pipeline$abc$estimators$2$gx_q$4 gx_q$4(
        .d(gx_q$4$d),
        .q(gx_q$4$q),
        .clock(gx_q$4$clock)
    );
    top$pipeline$abc$estimators$2$gx_q$5 gx_q$5(
        .d(gx_q$5$d),
        .q(gx_q$5$q),
        .clock(gx_q$5$clock)
    );
    top$pipeline$abc$estimators$2$gy_q$0 gy_q$0(
        .d(gy_q$0$d),
        .q(gy_q$0$q),
        .clock(gy_q$0$clock)
    );
    top$pipeline$abc$estimators$2$gy_q$1 gy_q$1(
        .d(gy_q$1$d),
        .q(gy_q$1$q),
        .clock(gy_q$1$clock)
    );
    top$pipeline$abc$estimators$2$gy_q$2 gy_q$2(
        .d(gy_q$2$d),
        .q(gy_q$2$q),
        .clock(gy_q$2$clock)
    );
    top$pipeline$abc$estimators$2$gy_q$3 gy_q$3(
        .d(gy_q$3$d),
        .q(gy_q$3$q),
        .clock(gy_q$3$clock)
    );
    top$pipeline$abc$estimators$2$gy_q$4 gy_q$4(
        .d(gy_q$4$d),
        .q(gy_q$4$q),
        .clock(gy_q$4$clock)
    );
    top$pipeline$abc$estimators$2$gy_q$5 gy_q$5(
        .d(gy_q$5$d),
        .q(gy_q$5$q),
        .clock(gy_q$5$clock)
    );
    top$pipeline$abc$estimators$2$gr_q$0 gr_q$0(
        .d(gr_q$0$d),
        .q(gr_q$0$q),
        .clock(gr_q$0$clock)
    );
    top$pipeline$abc$estimators$2$gr_q$1 gr_q$1(
        .d(gr_q$1$d),
        .q(gr_q$1$q),
        .clock(gr_q$1$clock)
    );
    top$pipeline$abc$estimators$2$gr_q$2 gr_q$2(
        .d(gr_q$2$d),
        .q(gr_q$2$q),
        .clock(gr_q$2$clock)
    );
    top$pipeline$abc$estimators$2$gr_q$3 gr_q$3(
        .d(gr_q$3$d),
        .q(gr_q$3$q),
        .clock(gr_q$3$clock)
    );
    top$pipeline$abc$estimators$2$gr_q$4 gr_q$4(
        .d(gr_q$4$d),
        .q(gr_q$4$q),
        .clock(gr_q$4$clock)
    );
    top$pipeline$abc$estimators$2$gr_q$5 gr_q$5(
        .d(gr_q$5$d),
        .q(gr_q$5$q),
        .clock(gr_q$5$clock)
    );
    top$pipeline$abc$estimators$2$dx_neg_q$0 dx_neg_q$0(
        .d(dx_neg_q$0$d),
        .q(dx_neg_q$0$q),
        .clock(dx_neg_q$0$clock)
    );
    top$pipeline$abc$estimators$2$dx_neg_q$1 dx_neg_q$1(
        .d(dx_neg_q$1$d),
        .q(dx_neg_q$1$q),
        .clock(dx_neg_q$1$clock)
    );
    top$pipeline$abc$estimators$2$dx_neg_q$2 dx_neg_q$2(
        .d(dx_neg_q$2$d),
        .q(dx_neg_q$2$q),
        .clock(dx_neg_q$2$clock)
    );
    top$pipeline$abc$estimators$2$dx_neg_q$3 dx_neg_q$3(
        .d(dx_neg_q$3$d),
        .q(dx_neg_q$3$q),
        .clock(dx_neg_q$3$clock)
    );
    top$pipeline$abc$estimators$2$dx_neg_q$4 dx_neg_q$4(
        .d(dx_neg_q$4$d),
        .q(dx_neg_q$4$q),
        .clock(dx_neg_q$4$clock)
    );
    top$pipeline$abc$estimators$2$dx_mag_q$0 dx_mag_q$0(
        .d(dx_mag_q$0$d),
        .q(dx_mag_q$0$q),
        .clock(dx_mag_q$0$clock)
    );
    top$pipeline$abc$estimators$2$dx_mag_q$1 dx_mag_q$1(
        .d(dx_mag_q$1$d),
        .q(dx_mag_q$1$q),
        .clock(dx_mag_q$1$clock)
    );
    top$pipeline$abc$estimators$2$dx_mag_q$2 dx_mag_q$2(
        .d(dx_mag_q$2$d),
        .q(dx_mag_q$2$q),
        .clock(dx_mag_q$2$clock)
    );
    top$pipeline$abc$estimators$2$dx_mag_q$3 dx_mag_q$3(
        .d(dx_mag_q$3$d),
        .q(dx_mag_q$3$q),
        .clock(dx_mag_q$3$clock)
    );
    top$pipeline$abc$estimators$2$dx_mag_q$4 dx_mag_q$4(
        .d(dx_mag_q$4$d),
        .q(dx_mag_q$4$q),
        .clock(dx_mag_q$4$clock)
    );
    top$pipeline$abc$estimators$2$dy_neg_q$0 dy_neg_q$0(
        .d(dy_neg_q$0$d),
        .q(dy_neg_q$0$q),
        .clock(dy_neg_q$0$clock)
    );
    top$pipeline$abc$estimators$2$dy_neg_q$1 dy_neg_q$1(
        .d(dy_neg_q$1$d),
        .q(dy_neg_q$1$q),
        .clock(dy_neg_q$1$clock)
    );
    top$pipeline$abc$estimators$2$dy_neg_q$2 dy_neg_q$2(
        .d(dy_neg_q$2$d),
        .q(dy_neg_q$2$q),
        .clock(dy_neg_q$2$clock)
    );
    top$pipeline$abc$estimators$2$dy_neg_q$3 dy_neg_q$3(
        .d(dy_neg_q$3$d),
        .q(dy_neg_q$3$q),
        .clock(dy_neg_q$3$clock)
    );
    top$pipeline$abc$estimators$2$dy_neg_q$4 dy_neg_q$4(
        .d(dy_neg_q$4$d),
        .q(dy_neg_q$4$q),
        .clock(dy_neg_q$4$clock)
    );
    top$pipeline$abc$estimators$2$dy_mag_q$0 dy_mag_q$0(
        .d(dy_mag_q$0$d),
        .q(dy_mag_q$0$q),
        .clock(dy_mag_q$0$clock)
    );
    top$pipeline$abc$estimators$2$dy_mag_q$1 dy_mag_q$1(
        .d(dy_mag_q$1$d),
        .q(dy_mag_q$1$q),
        .clock(dy_mag_q$1$clock)
    );
    top$pipeline$abc$estimators$2$dy_mag_q$2 dy_mag_q$2(
        .d(dy_mag_q$2$d),
        .q(dy_mag_q$2$q),
        .clock(dy_mag_q$2$clock)
    );
    top$pipeline$abc$estimators$2$dy_mag_q$3 dy_mag_q$3(
        .d(dy_mag_q$3$d),
        .q(dy_mag_q$3$q),
        .clock(dy_mag_q$3$clock)
    );
    top$pipeline$abc$estimators$2$dy_mag_q$4 dy_mag_q$4(
        .d(dy_mag_q$4$d),
        .q(dy_mag_q$4$q),
        .clock(dy_mag_q$4$clock)
    );
    top$pipeline$abc$estimators$2$px px(
        .g(px$g),
        .d_neg(px$d_neg),
        .d_mag(px$d_mag),
        .y(px$y)
    );
    top$pipeline$abc$estimators$2$py py(
        .g(py$g),
        .d_neg(py$d_neg),
        .d_mag(py$d_mag),
        .y(py$y)
    );
    top$pipeline$abc$estimators$2$px_q px_q(
        .d(px_q$d),
        .q(px_q$q),
        .clock(px_q$clock)
    );
    top$pipeline$abc$estimators$2$py_q py_q(
        .d(py_q$d),
        .q(py_q$q),
        .clock(py_q$clock)
    );
    top$pipeline$abc$estimators$2$front_top front_top(
        .clock(front_top$clock),
        .a(front_top$a),
        .b(front_top$b),
        .w(front_top$w),
        .y(front_top$y)
    );
    top$pipeline$abc$estimators$2$front_bottom front_bottom(
        .clock(front_bottom$clock),
        .a(front_bottom$a),
        .b(front_bottom$b),
        .w(front_bottom$w),
        .y(front_bottom$y)
    );
    top$pipeline$abc$estimators$2$front_y front_y(
        .clock(front_y$clock),
        .a(front_y$a),
        .b(front_y$b),
        .w(front_y$w),
        .y(front_y$y)
    );
    top$pipeline$abc$estimators$2$back_top back_top(
        .clock(back_top$clock),
        .a(back_top$a),
        .b(back_top$b),
        .w(back_top$w),
        .y(back_top$y)
    );
    top$pipeline$abc$estimators$2$back_bottom back_bottom(
        .clock(back_bottom$clock),
        .a(back_bottom$a),
        .b(back_bottom$b),
        .w(back_bottom$w),
        .y(back_bottom$y)
    );
    top$pipeline$abc$estimators$2$back_y back_y(
        .clock(back_y$clock),
        .a(back_y$a),
        .b(back_y$b),
        .w(back_y$w),
        .y(back_y$y)
    );
    top$pipeline$abc$estimators$2$sat_x sat_x(
        .v(sat_x$v),
        .y(sat_x$y)
    );
    top$pipeline$abc$estimators$2$sat_y sat_y(
        .v(sat_y$v),
        .y(sat_y$y)
    );
    top$pipeline$abc$estimators$2$sat_z sat_z(
        .v(sat_z$v),
        .y(sat_z$y)
    );
    top$pipeline$abc$estimators$2$gx_out gx_out(
        .d(gx_out$d),
        .q(gx_out$q),
        .clock(gx_out$clock)
    );
    top$pipeline$abc$estimators$2$gy_out gy_out(
        .d(gy_out$d),
        .q(gy_out$q),
        .clock(gy_out$clock)
    );
    top$pipeline$abc$estimators$2$gz_out gz_out(
        .d(gz_out$d),
        .q(gz_out$q),
        .clock(gz_out$clock)
    );
    top$pipeline$abc$estimators$2$centre_q$0 centre_q$0(
        .d(centre_q$0$d),
        .q(centre_q$0$q),
        .clock(centre_q$0$clock)
    );
    top$pipeline$abc$estimators$2$centre_q$1 centre_q$1(
        .d(centre_q$1$d),
        .q(centre_q$1$q),
        .clock(centre_q$1$clock)
    );
    top$pipeline$abc$estimators$2$centre_q$2 centre_q$2(
        .d(centre_q$2$d),
        .q(centre_q$2$q),
        .clock(centre_q$2$clock)
    );
    top$pipeline$abc$estimators$2$centre_q$3 centre_q$3(
        .d(centre_q$3$d),
        .q(centre_q$3$q),
        .clock(centre_q$3$clock)
    );
    top$pipeline$abc$estimators$2$centre_q$4 centre_q$4(
        .d(centre_q$4$d),
        .q(centre_q$4$q),
        .clock(centre_q$4$clock)
    );
    top$pipeline$abc$estimators$2$centre_q$5 centre_q$5(
        .d(centre_q$5$d),
        .q(centre_q$5$q),
        .clock(centre_q$5$clock)
    );
    top$pipeline$abc$estimators$2$centre_q$6 centre_q$6(
        .d(centre_q$6$d),
        .q(centre_q$6$q),
        .clock(centre_q$6$clock)
    );
    
    // Update code
    always @(*) begin
        px_q$clock = clock;
        py_q$clock = clock;
        gx_out$clock = clock;
        gy_out$clock = clock;
        gz_out$clock = clock;
        px_q$d = px_q$q;
        py_q$d = py_q$q;
        gx_out$d = gx_out$q;
        gy_out$d = gy_out$q;
        gz_out$d = gz_out$q;
        centre_q$0$clock = clock;
        centre_q$1$clock = clock;
        centre_q$2$clock = clock;
        centre_q$3$clock = clock;
        centre_q$4$clock = clock;
        centre_q$5$clock = clock;
        centre_q$6$clock = clock;
        centre_q$0$d = centre;
        centre_q$1$d = centre_q$0$q;
        centre_q$2$d = centre_q$1$q;
        centre_q$3$d = centre_q$2$q;
        centre_q$4$d = centre_q$3$q;
        centre_q$5$d = centre_q$4$q;
        centre_q$6$d = centre_q$5$q;
        sample = centre_q$6$q;
        gx_q$0$clock = clock;
        gy_q$0$clock = clock;
        gr_q$0$clock = clock;
        gx_q$1$clock = clock;
        gy_q$1$clock = clock;
        gr_q$1$clock = clock;
        gx_q$2$clock = clock;
        gy_q$2$clock = clock;
        gr_q$2$clock = clock;
        gx_q$3$clock = clock;
        gy_q$3$clock = clock;
        gr_q$3$clock = clock;
        gx_q$4$clock = clock;
        gy_q$4$clock = clock;
        gr_q$4$clock = clock;
        gx_q$5$clock = clock;
        gy_q$5$clock = clock;
        gr_q$5$clock = clock;
        b10x_q$0$clock = clock;
        b10y_q$0$clock = clock;
        b10z_q$0$clock = clock;
        b10x_q$1$clock = clock;
        b10y_q$1$clock = clock;
        b10z_q$1$clock = clock;
        dx_neg_q$0$clock = clock;
        dx_mag_q$0$clock = clock;
        dy_neg_q$0$clock = clock;
        dy_mag_q$0$clock = clock;
        dx_neg_q$1$clock = clock;
        dx_mag_q$1$clock = clock;
        dy_neg_q$1$clock = clock;
        dy_mag_q$1$clock = clock;
        dx_neg_q$2$clock = clock;
        dx_mag_q$2$clock = clock;
        dy_neg_q$2$clock = clock;
        dy_mag_q$2$clock = clock;
        dx_neg_q$3$clock = clock;
        dx_mag_q$3$clock = clock;
        dy_neg_q$3$clock = clock;
        dy_mag_q$3$clock = clock;
        dx_neg_q$4$clock = clock;
        dx_mag_q$4$clock = clock;
        dy_neg_q$4$clock = clock;
        dy_mag_q$4$clock = clock;
        front_top$clock = clock;
        front_bottom$clock = clock;
        front_y$clock = clock;
        back_top$clock = clock;
        back_bottom$clock = clock;
        back_y$clock = clock;
        gx_q$0$d = xp - xm;
        gy_q$0$d = yp - ym;
        gr_q$0$d = kp4 - km4;
        gx_q$1$d = gx_q$0$q;
        gy_q$1$d = gy_q$0$q;
        gr_q$1$d = gr_q$0$q;
        gx_q$2$d = gx_q$1$q;
        gy_q$2$d = gy_q$1$q;
        gr_q$2$d = gr_q$1$q;
        gx_q$3$d = gx_q$2$q;
        gy_q$3$d = gy_q$2$q;
        gr_q$3$d = gr_q$2$q;
        gx_q$4$d = gx_q$3$q;
        gy_q$4$d = gy_q$3$q;
        gr_q$4$d = gr_q$3$q;
        gx_q$5$d = gx_q$4$q;
        gy_q$5$d = gy_q$4$q;
        gr_q$5$d = gr_q$4$q;
        sums26$clock = clock;
        sums26$xp = xp;
        sums26$xm = xm;
        sums26$yp = yp;
        sums26$ym = ym;
        sums26$c0 = c0;
        sums26$c2 = c2;
        sums26$c6 = c6;
        sums26$c8 = c8;
        sums26$kp0 = kp0;
        sums26$kp1 = kp1;
        sums26$kp2 = kp2;
        sums26$kp3 = kp3;
        sums26$kp4 = kp4;
        sums26$kp5 = kp5;
        sums26$kp6 = kp6;
        sums26$kp7 = kp7;
        sums26$kp8 = kp8;
        sums26$km0 = km0;
        sums26$km1 = km1;
        sums26$km2 = km2;
        sums26$km3 = km3;
        sums26$km4 = km4;
        sums26$km5 = km5;
        sums26$km6 = km6;
        sums26$km7 = km7;
        sums26$km8 = km8;
        basis10$clock = clock;
        basis10$xp = xp;
        basis10$xm = xm;
        basis10$yp = yp;
        basis10$ym = ym;
        basis10$kp1 = kp1;
        basis10$kp3 = kp3;
        basis10$kp4 = kp4;
        basis10$kp5 = kp5;
        basis10$kp7 = kp7;
        basis10$km1 = km1;
        basis10$km3 = km3;
        basis10$km4 = km4;
        basis10$km5 = km5;
        basis10$km7 = km7;
        basis10$dx_neg = dx_neg;
        basis10$dx_mag = dx_mag;
        basis10$dy_neg = dy_neg;
        basis10$dy_mag = dy_mag;
        basis10$weights = weights10;
        basis10$basis_x = basis10_x;
        basis10$basis_y = basis10_y;
        basis10$basis_z = basis10_z;
        if (n26) begin
            gx_q$2$d = sums26$gx;
            gy_q$2$d = sums26$gy;
            gr_q$2$d = sums26$gr;
        end
        dx_neg_q$0$d = dx_neg;
        dx_mag_q$0$d = dx_mag;
        dy_neg_q$0$d = dy_neg;
        dy_mag_q$0$d = dy_mag;
        dx_neg_q$1$d = dx_neg_q$0$q;
        dx_mag_q$1$d = dx_mag_q$0$q;
        dy_neg_q$1$d = dy_neg_q$0$q;
        dy_mag_q$1$d = dy_mag_q$0$q;
        dx_neg_q$2$d = dx_neg_q$1$q;
        dx_mag_q$2$d = dx_mag_q$1$q;
        dy_neg_q$2$d = dy_neg_q$1$q;
        dy_mag_q$2$d = dy_mag_q$1$q;
        dx_neg_q$3$d = dx_neg_q$2$q;
        dx_mag_q$3$d = dx_mag_q$2$q;
        dy_neg_q$3$d = dy_neg_q$2$q;
        dy_mag_q$3$d = dy_mag_q$2$q;
        dx_neg_q$4$d = dx_neg_q$3$q;
        dx_mag_q$4$d = dx_mag_q$3$q;
        dy_neg_q$4$d = dy_neg_q$3$q;
        dy_mag_q$4$d = dy_mag_q$3$q;
        px$g = gx_q$4$q;
        px$d_neg = dx_neg_q$4$q;
        px$d_mag = dx_mag_q$4$q;
        py$g = gy_q$4$q;
        py$d_neg = dy_neg_q$4$q;
        py$d_mag = dy_mag_q$4$q;
        px_q$d = px$y;
        py_q$d = py$y;
        shear_sum = px_q$q + py_q$q + half;
        shear = shear_sum >> shift;
        if (shear_sum['h3f]) begin
            shear = ~((~shear_sum) >> shift);
        end
        sx_pos = ~dx_neg & |dx_mag;
        sx_neg = dx_neg & |dx_mag;
        sy_pos = ~dy_neg & |dy_mag;
        sy_neg = dy_neg & |dy_mag;
        front_row$0 = kp3;
        back_row$0 = km3;
        if (sy_pos) begin
            front_row$0 = kp6;
            back_row$0 = km0;
        end
        if (sy_neg) begin
            front_row$0 = kp0;
            back_row$0 = km6;
        end
        front_row$1 = kp4;
        back_row$1 = km4;
        if (sy_pos) begin
            front_row$1 = kp7;
            back_row$1 = km1;
        end
        if (sy_neg) begin
            front_row$1 = kp1;
            back_row$1 = km7;
        end
        front_row$2 = kp5;
        back_row$2 = km5;
        if (sy_pos) begin
            front_row$2 = kp8;
            back_row$2 = km2;
        end
        if (sy_neg) begin
            front_row$2 = kp2;
            back_row$2 = km8;
        end
        front_x = kp4;
        front_xy = front_row$1;
        back_x = km4;
        back_xy = back_row$1;
        if (sx_pos) begin
            front_x = kp5;
            front_xy = front_row$2;
            back_x = km3;
            back_xy = back_row$0;
        end
        if (sx_neg) begin
            front_x = kp3;
            front_xy = front_row$0;
            back_x = km5;
            back_xy = back_row$2;
        end
        front_top$a = kp4;
        front_top$b = front_x;
        front_top$w = dx_mag;
        front_bottom$a = front_row$1;
        front_bottom$b = front_xy;
        front_bottom$w = dx_mag;
        front_y$a = front_top$y;
        front_y$b = front_bottom$y;
        front_y$w = dy_mag_q$2$q;
        back_top$a = km4;
        back_top$b = back_x;
        back_top$w = dx_mag;
        back_bottom$a = back_row$1;
        back_bottom$b = back_xy;
        back_bottom$w = dx_mag;
        back_y$a = back_top$y;
        back_y$b = back_bottom$y;
        back_y$w = dy_mag_q$2$q;
        gr_wide = 64'(gr_q$5$q);
        if (gr_q$5$q['h1f]) begin
            gr_wide = 64'(gr_q$5$q) | sign_ext;
        end
        gz_wide = gr_wide - shear;
        if (n12) begin
            gz_wide = 64'(front_y$y) - 64'(back_y$y);
        end
        sat_x$v = 64'(gx_q$5$q);
        if (gx_q$5$q['h1f]) begin
            sat_x$v = 64'(gx_q$5$q) | sign_ext;
        end
        sat_y$v = 64'(gy_q$5$q);
        if (gy_q$5$q['h1f]) begin
            sat_y$v = 64'(gy_q$5$q) | sign_ext;
        end
        sat_z$v = gz_wide;
        b10x_q$0$d = basis10$gx;
        b10y_q$0$d = basis10$gy;
        b10z_q$0$d = basis10$gz;
        b10x_q$1$d = b10x_q$0$q;
        b10y_q$1$d = b10y_q$0$q;
        b10z_q$1$d = b10z_q$0$q;
        if (n10) begin
            sat_x$v = b10x_q$1$q;
            sat_y$v = b10y_q$1$q;
            sat_z$v = b10z_q$1$q;
        end
        gx_out$d = sat_x$y;
        gy_out$d = sat_y$y;
        gz_out$d = sat_z$y;
        gx = gx_out$q;
        gy = gy_out$q;
        gz = gz_out$q;
    end
    
endmodule // top$pipeline$abc$estimators$2
module top$pipeline$abc$estimators$2$b10x_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$b10x_q$0
module top$pipeline$abc$estimators$2$b10x_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$b10x_q$1
module top$pipeline$abc$estimators$2$b10y_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$b10y_q$0
module top$pipeline$abc$estimators$2$b10y_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$b10y_q$1
module top$pipeline$abc$estimators$2$b10z_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$b10z_q$0
module top$pipeline$abc$estimators$2$b10z_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$b10z_q$1
module top$pipeline$abc$estimators$2$back_bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$2$back_bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$2$back_bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$2$back_bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$2$back_bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$2$back_bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$2$back_bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$2$back_bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$2$back_bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$2$back_bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$2$back_bottom
module top$pipeline$abc$estimators$2$back_bottom$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_bottom$a_q
module top$pipeline$abc$estimators$2$back_bottom$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_bottom$a_q2
module top$pipeline$abc$estimators$2$back_bottom$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_bottom$diff_q
module top$pipeline$abc$estimators$2$back_bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$2$back_bottom$narrow
module top$pipeline$abc$estimators$2$back_bottom$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_bottom$prod_q
module top$pipeline$abc$estimators$2$back_bottom$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_bottom$up_q
module top$pipeline$abc$estimators$2$back_bottom$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_bottom$up_q2
module top$pipeline$abc$estimators$2$back_bottom$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_bottom$w_q
module top$pipeline$abc$estimators$2$back_bottom$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_bottom$y_q
module top$pipeline$abc$estimators$2$back_top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$2$back_top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$2$back_top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$2$back_top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$2$back_top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$2$back_top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$2$back_top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$2$back_top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$2$back_top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$2$back_top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$2$back_top
module top$pipeline$abc$estimators$2$back_top$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_top$a_q
module top$pipeline$abc$estimators$2$back_top$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_top$a_q2
module top$pipeline$abc$estimators$2$back_top$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_top$diff_q
module top$pipeline$abc$estimators$2$back_top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$2$back_top$narrow
module top$pipeline$abc$estimators$2$back_top$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_top$prod_q
module top$pipeline$abc$estimators$2$back_top$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_top$up_q
module top$pipeline$abc$estimators$2$back_top$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_top$up_q2
module top$pipeline$abc$estimators$2$back_top$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_top$w_q
module top$pipeline$abc$estimators$2$back_top$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_top$y_q
module top$pipeline$abc$estimators$2$back_y(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$2$back_y$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$2$back_y$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$2$back_y$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$2$back_y$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$2$back_y$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$2$back_y$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$2$back_y$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$2$back_y$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$2$back_y$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$2$back_y
module top$pipeline$abc$estimators$2$back_y$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_y$a_q
module top$pipeline$abc$estimators$2$back_y$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_y$a_q2
module top$pipeline$abc$estimators$2$back_y$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_y$diff_q
module top$pipeline$abc$estimators$2$back_y$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$2$back_y$narrow
module top$pipeline$abc$estimators$2$back_y$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_y$prod_q
module top$pipeline$abc$estimators$2$back_y$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_y$up_q
module top$pipeline$abc$estimators$2$back_y$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_y$up_q2
module top$pipeline$abc$estimators$2$back_y$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_y$w_q
module top$pipeline$abc$estimators$2$back_y$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$back_y$y_q
module top$pipeline$abc$estimators$2$centre_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$centre_q$0
module top$pipeline$abc$estimators$2$centre_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$centre_q$1
module top$pipeline$abc$estimators$2$centre_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$centre_q$2
module top$pipeline$abc$estimators$2$centre_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$centre_q$3
module top$pipeline$abc$estimators$2$centre_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$centre_q$4
module top$pipeline$abc$estimators$2$centre_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$centre_q$5
module top$pipeline$abc$estimators$2$centre_q$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$centre_q$6
module top$pipeline$abc$estimators$2$dx_mag_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dx_mag_q$0
module top$pipeline$abc$estimators$2$dx_mag_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dx_mag_q$1
module top$pipeline$abc$estimators$2$dx_mag_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dx_mag_q$2
module top$pipeline$abc$estimators$2$dx_mag_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dx_mag_q$3
module top$pipeline$abc$estimators$2$dx_mag_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dx_mag_q$4
module top$pipeline$abc$estimators$2$dx_neg_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dx_neg_q$0
module top$pipeline$abc$estimators$2$dx_neg_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dx_neg_q$1
module top$pipeline$abc$estimators$2$dx_neg_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dx_neg_q$2
module top$pipeline$abc$estimators$2$dx_neg_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dx_neg_q$3
module top$pipeline$abc$estimators$2$dx_neg_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dx_neg_q$4
module top$pipeline$abc$estimators$2$dy_mag_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dy_mag_q$0
module top$pipeline$abc$estimators$2$dy_mag_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dy_mag_q$1
module top$pipeline$abc$estimators$2$dy_mag_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dy_mag_q$2
module top$pipeline$abc$estimators$2$dy_mag_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dy_mag_q$3
module top$pipeline$abc$estimators$2$dy_mag_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dy_mag_q$4
module top$pipeline$abc$estimators$2$dy_neg_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dy_neg_q$0
module top$pipeline$abc$estimators$2$dy_neg_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dy_neg_q$1
module top$pipeline$abc$estimators$2$dy_neg_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dy_neg_q$2
module top$pipeline$abc$estimators$2$dy_neg_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dy_neg_q$3
module top$pipeline$abc$estimators$2$dy_neg_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$dy_neg_q$4
module top$pipeline$abc$estimators$2$front_bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$2$front_bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$2$front_bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$2$front_bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$2$front_bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$2$front_bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$2$front_bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$2$front_bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$2$front_bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$2$front_bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$2$front_bottom
module top$pipeline$abc$estimators$2$front_bottom$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_bottom$a_q
module top$pipeline$abc$estimators$2$front_bottom$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_bottom$a_q2
module top$pipeline$abc$estimators$2$front_bottom$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_bottom$diff_q
module top$pipeline$abc$estimators$2$front_bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$2$front_bottom$narrow
module top$pipeline$abc$estimators$2$front_bottom$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_bottom$prod_q
module top$pipeline$abc$estimators$2$front_bottom$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_bottom$up_q
module top$pipeline$abc$estimators$2$front_bottom$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_bottom$up_q2
module top$pipeline$abc$estimators$2$front_bottom$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_bottom$w_q
module top$pipeline$abc$estimators$2$front_bottom$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_bottom$y_q
module top$pipeline$abc$estimators$2$front_top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$2$front_top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$2$front_top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$2$front_top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$2$front_top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$2$front_top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$2$front_top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$2$front_top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$2$front_top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$2$front_top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$2$front_top
module top$pipeline$abc$estimators$2$front_top$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_top$a_q
module top$pipeline$abc$estimators$2$front_top$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_top$a_q2
module top$pipeline$abc$estimators$2$front_top$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_top$diff_q
module top$pipeline$abc$estimators$2$front_top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$2$front_top$narrow
module top$pipeline$abc$estimators$2$front_top$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_top$prod_q
module top$pipeline$abc$estimators$2$front_top$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_top$up_q
module top$pipeline$abc$estimators$2$front_top$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_top$up_q2
module top$pipeline$abc$estimators$2$front_top$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_top$w_q
module top$pipeline$abc$estimators$2$front_top$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_top$y_q
module top$pipeline$abc$estimators$2$front_y(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$2$front_y$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$2$front_y$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$2$front_y$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$2$front_y$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$2$front_y$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$2$front_y$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$2$front_y$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$2$front_y$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$2$front_y$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$2$front_y
module top$pipeline$abc$estimators$2$front_y$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_y$a_q
module top$pipeline$abc$estimators$2$front_y$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_y$a_q2
module top$pipeline$abc$estimators$2$front_y$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_y$diff_q
module top$pipeline$abc$estimators$2$front_y$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$2$front_y$narrow
module top$pipeline$abc$estimators$2$front_y$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_y$prod_q
module top$pipeline$abc$estimators$2$front_y$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_y$up_q
module top$pipeline$abc$estimators$2$front_y$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_y$up_q2
module top$pipeline$abc$estimators$2$front_y$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_y$w_q
module top$pipeline$abc$estimators$2$front_y$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$front_y$y_q
module top$pipeline$abc$estimators$2$gr_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gr_q$0
module top$pipeline$abc$estimators$2$gr_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gr_q$1
module top$pipeline$abc$estimators$2$gr_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gr_q$2
module top$pipeline$abc$estimators$2$gr_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gr_q$3
module top$pipeline$abc$estimators$2$gr_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gr_q$4
module top$pipeline$abc$estimators$2$gr_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gr_q$5
module top$pipeline$abc$estimators$2$gx_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gx_out
module top$pipeline$abc$estimators$2$gx_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gx_q$0
module top$pipeline$abc$estimators$2$gx_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gx_q$1
module top$pipeline$abc$estimators$2$gx_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gx_q$2
module top$pipeline$abc$estimators$2$gx_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gx_q$3
module top$pipeline$abc$estimators$2$gx_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gx_q$4
module top$pipeline$abc$estimators$2$gx_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gx_q$5
module top$pipeline$abc$estimators$2$gy_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gy_out
module top$pipeline$abc$estimators$2$gy_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gy_q$0
module top$pipeline$abc$estimators$2$gy_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gy_q$1
module top$pipeline$abc$estimators$2$gy_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gy_q$2
module top$pipeline$abc$estimators$2$gy_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gy_q$3
module top$pipeline$abc$estimators$2$gy_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gy_q$4
module top$pipeline$abc$estimators$2$gy_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gy_q$5
module top$pipeline$abc$estimators$2$gz_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$gz_out
module top$pipeline$abc$estimators$2$px(g,d_neg,d_mag,y);
    
    // Module arguments
    input wire  [31:0] g;
    input wire  d_neg;
    input wire  [15:0] d_mag;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] mag;
    reg  [63:0] prod;
    
    // Update code
    reg  [63:0] y_pass;
    always @(*) begin
        mag = g;
        if (g['h1f]) begin
            mag = ~g + 'h1;
        end
        prod = 64'(mag[('h0)+:(16)] * d_mag);
        if (wide) begin
            prod = (64'(mag[('h10)+:(16)] * d_mag) << 'h10) + 64'(mag[('h0)+:(16)] * d_mag);
        end
        y_pass = prod;
        if (g['h1f] ^ d_neg) begin
            y_pass = ~prod + 'h1;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$2$px
module top$pipeline$abc$estimators$2$px_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$px_q
module top$pipeline$abc$estimators$2$py(g,d_neg,d_mag,y);
    
    // Module arguments
    input wire  [31:0] g;
    input wire  d_neg;
    input wire  [15:0] d_mag;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] mag;
    reg  [63:0] prod;
    
    // Update code
    reg  [63:0] y_pass;
    always @(*) begin
        mag = g;
        if (g['h1f]) begin
            mag = ~g + 'h1;
        end
        prod = 64'(mag[('h0)+:(16)] * d_mag);
        if (wide) begin
            prod = (64'(mag[('h10)+:(16)] * d_mag) << 'h10) + 64'(mag[('h0)+:(16)] * d_mag);
        end
        y_pass = prod;
        if (g['h1f] ^ d_neg) begin
            y_pass = ~prod + 'h1;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$2$py
module top$pipeline$abc$estimators$2$py_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$2$py_q
module top$pipeline$abc$estimators$2$sat_x(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$2$sat_x
module top$pipeline$abc$estimators$2$sat_y(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$2$sat_y
module top$pipeline$abc$estimators$2$sat_z(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$2$sat_z
module top$pipeline$abc$estimators$3(clock,xp,xm,yp,ym,kp0,kp1,kp2,kp3,kp4,kp5,kp6,kp7,kp8,km0,km1,km2,km3,km4,km5,km6,km7,km8,c0,c2,c6,c8,weights10,basis10_x,basis10_y,basis10_z,dx_neg,dx_mag,dy_neg,dy_mag,centre,sample,gx,gy,gz);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] xp;
    input wire  [31:0] xm;
    input wire  [31:0] yp;
    input wire  [31:0] ym;
    input wire  [31:0] kp0;
    input wire  [31:0] kp1;
    input wire  [31:0] kp2;
    input wire  [31:0] kp3;
    input wire  [31:0] kp4;
    input wire  [31:0] kp5;
    input wire  [31:0] kp6;
    input wire  [31:0] kp7;
    input wire  [31:0] kp8;
    input wire  [31:0] km0;
    input wire  [31:0] km1;
    input wire  [31:0] km2;
    input wire  [31:0] km3;
    input wire  [31:0] km4;
    input wire  [31:0] km5;
    input wire  [31:0] km6;
    input wire  [31:0] km7;
    input wire  [31:0] km8;
    input wire  [31:0] c0;
    input wire  [31:0] c2;
    input wire  [31:0] c6;
    input wire  [31:0] c8;
    input wire  [63:0] weights10;
    input wire  [63:0] basis10_x;
    input wire  [63:0] basis10_y;
    input wire  [63:0] basis10_z;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [31:0] centre;
    output reg  [31:0] sample;
    output reg  [31:0] gx;
    output reg  [31:0] gy;
    output reg  [31:0] gz;
    
    // Constant declarations
    localparam  n12 = 1'b1;
    localparam  n26 = 1'b0;
    localparam  n10 = 1'b0;
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  sign_ext = 64'hffffffff00000000;
    
    // Stub signals
    reg  sums26$clock;
    reg  [31:0] sums26$xp;
    reg  [31:0] sums26$xm;
    reg  [31:0] sums26$yp;
    reg  [31:0] sums26$ym;
    reg  [31:0] sums26$c0;
    reg  [31:0] sums26$c2;
    reg  [31:0] sums26$c6;
    reg  [31:0] sums26$c8;
    reg  [31:0] sums26$kp0;
    reg  [31:0] sums26$kp1;
    reg  [31:0] sums26$kp2;
    reg  [31:0] sums26$kp3;
    reg  [31:0] sums26$kp4;
    reg  [31:0] sums26$kp5;
    reg  [31:0] sums26$kp6;
    reg  [31:0] sums26$kp7;
    reg  [31:0] sums26$kp8;
    reg  [31:0] sums26$km0;
    reg  [31:0] sums26$km1;
    reg  [31:0] sums26$km2;
    reg  [31:0] sums26$km3;
    reg  [31:0] sums26$km4;
    reg  [31:0] sums26$km5;
    reg  [31:0] sums26$km6;
    reg  [31:0] sums26$km7;
    reg  [31:0] sums26$km8;
    wire  [31:0] sums26$gx = 'h0;
    wire  [31:0] sums26$gy = 'h0;
    wire  [31:0] sums26$gr = 'h0;
    reg  basis10$clock;
    reg  [31:0] basis10$xp;
    reg  [31:0] basis10$xm;
    reg  [31:0] basis10$yp;
    reg  [31:0] basis10$ym;
    reg  [31:0] basis10$kp1;
    reg  [31:0] basis10$kp3;
    reg  [31:0] basis10$kp4;
    reg  [31:0] basis10$kp5;
    reg  [31:0] basis10$kp7;
    reg  [31:0] basis10$km1;
    reg  [31:0] basis10$km3;
    reg  [31:0] basis10$km4;
    reg  [31:0] basis10$km5;
    reg  [31:0] basis10$km7;
    reg  basis10$dx_neg;
    reg  [15:0] basis10$dx_mag;
    reg  basis10$dy_neg;
    reg  [15:0] basis10$dy_mag;
    reg  [63:0] basis10$weights;
    reg  [63:0] basis10$basis_x;
    reg  [63:0] basis10$basis_y;
    reg  [63:0] basis10$basis_z;
    wire  [63:0] basis10$gx = 'h0;
    wire  [63:0] basis10$gy = 'h0;
    wire  [63:0] basis10$gz = 'h0;
    reg  [63:0] b10x_q$0$d;
    wire  [63:0] b10x_q$0$q;
    reg  b10x_q$0$clock;
    reg  [63:0] b10x_q$1$d;
    wire  [63:0] b10x_q$1$q;
    reg  b10x_q$1$clock;
    reg  [63:0] b10y_q$0$d;
    wire  [63:0] b10y_q$0$q;
    reg  b10y_q$0$clock;
    reg  [63:0] b10y_q$1$d;
    wire  [63:0] b10y_q$1$q;
    reg  b10y_q$1$clock;
    reg  [63:0] b10z_q$0$d;
    wire  [63:0] b10z_q$0$q;
    reg  b10z_q$0$clock;
    reg  [63:0] b10z_q$1$d;
    wire  [63:0] b10z_q$1$q;
    reg  b10z_q$1$clock;
    reg  [31:0] gx_q$0$d;
    wire  [31:0] gx_q$0$q;
    reg  gx_q$0$clock;
    reg  [31:0] gx_q$1$d;
    wire  [31:0] gx_q$1$q;
    reg  gx_q$1$clock;
    reg  [31:0] gx_q$2$d;
    wire  [31:0] gx_q$2$q;
    reg  gx_q$2$clock;
    reg  [31:0] gx_q$3$d;
    wire  [31:0] gx_q$3$q;
    reg  gx_q$3$clock;
    reg  [31:0] gx_q$4$d;
    wire  [31:0] gx_q$4$q;
    reg  gx_q$4$clock;
    reg  [31:0] gx_q$5$d;
    wire  [31:0] gx_q$5$q;
    reg  gx_q$5$clock;
    reg  [31:0] gy_q$0$d;
    wire  [31:0] gy_q$0$q;
    reg  gy_q$0$clock;
    reg  [31:0] gy_q$1$d;
    wire  [31:0] gy_q$1$q;
    reg  gy_q$1$clock;
    reg  [31:0] gy_q$2$d;
    wire  [31:0] gy_q$2$q;
    reg  gy_q$2$clock;
    reg  [31:0] gy_q$3$d;
    wire  [31:0] gy_q$3$q;
    reg  gy_q$3$clock;
    reg  [31:0] gy_q$4$d;
    wire  [31:0] gy_q$4$q;
    reg  gy_q$4$clock;
    reg  [31:0] gy_q$5$d;
    wire  [31:0] gy_q$5$q;
    reg  gy_q$5$clock;
    reg  [31:0] gr_q$0$d;
    wire  [31:0] gr_q$0$q;
    reg  gr_q$0$clock;
    reg  [31:0] gr_q$1$d;
    wire  [31:0] gr_q$1$q;
    reg  gr_q$1$clock;
    reg  [31:0] gr_q$2$d;
    wire  [31:0] gr_q$2$q;
    reg  gr_q$2$clock;
    reg  [31:0] gr_q$3$d;
    wire  [31:0] gr_q$3$q;
    reg  gr_q$3$clock;
    reg  [31:0] gr_q$4$d;
    wire  [31:0] gr_q$4$q;
    reg  gr_q$4$clock;
    reg  [31:0] gr_q$5$d;
    wire  [31:0] gr_q$5$q;
    reg  gr_q$5$clock;
    reg  dx_neg_q$0$d;
    wire  dx_neg_q$0$q;
    reg  dx_neg_q$0$clock;
    reg  dx_neg_q$1$d;
    wire  dx_neg_q$1$q;
    reg  dx_neg_q$1$clock;
    reg  dx_neg_q$2$d;
    wire  dx_neg_q$2$q;
    reg  dx_neg_q$2$clock;
    reg  dx_neg_q$3$d;
    wire  dx_neg_q$3$q;
    reg  dx_neg_q$3$clock;
    reg  dx_neg_q$4$d;
    wire  dx_neg_q$4$q;
    reg  dx_neg_q$4$clock;
    reg  [15:0] dx_mag_q$0$d;
    wire  [15:0] dx_mag_q$0$q;
    reg  dx_mag_q$0$clock;
    reg  [15:0] dx_mag_q$1$d;
    wire  [15:0] dx_mag_q$1$q;
    reg  dx_mag_q$1$clock;
    reg  [15:0] dx_mag_q$2$d;
    wire  [15:0] dx_mag_q$2$q;
    reg  dx_mag_q$2$clock;
    reg  [15:0] dx_mag_q$3$d;
    wire  [15:0] dx_mag_q$3$q;
    reg  dx_mag_q$3$clock;
    reg  [15:0] dx_mag_q$4$d;
    wire  [15:0] dx_mag_q$4$q;
    reg  dx_mag_q$4$clock;
    reg  dy_neg_q$0$d;
    wire  dy_neg_q$0$q;
    reg  dy_neg_q$0$clock;
    reg  dy_neg_q$1$d;
    wire  dy_neg_q$1$q;
    reg  dy_neg_q$1$clock;
    reg  dy_neg_q$2$d;
    wire  dy_neg_q$2$q;
    reg  dy_neg_q$2$clock;
    reg  dy_neg_q$3$d;
    wire  dy_neg_q$3$q;
    reg  dy_neg_q$3$clock;
    reg  dy_neg_q$4$d;
    wire  dy_neg_q$4$q;
    reg  dy_neg_q$4$clock;
    reg  [15:0] dy_mag_q$0$d;
    wire  [15:0] dy_mag_q$0$q;
    reg  dy_mag_q$0$clock;
    reg  [15:0] dy_mag_q$1$d;
    wire  [15:0] dy_mag_q$1$q;
    reg  dy_mag_q$1$clock;
    reg  [15:0] dy_mag_q$2$d;
    wire  [15:0] dy_mag_q$2$q;
    reg  dy_mag_q$2$clock;
    reg  [15:0] dy_mag_q$3$d;
    wire  [15:0] dy_mag_q$3$q;
    reg  dy_mag_q$3$clock;
    reg  [15:0] dy_mag_q$4$d;
    wire  [15:0] dy_mag_q$4$q;
    reg  dy_mag_q$4$clock;
    reg  [31:0] px$g;
    reg  px$d_neg;
    reg  [15:0] px$d_mag;
    wire  [63:0] px$y;
    reg  [31:0] py$g;
    reg  py$d_neg;
    reg  [15:0] py$d_mag;
    wire  [63:0] py$y;
    reg  [63:0] px_q$d;
    wire  [63:0] px_q$q;
    reg  px_q$clock;
    reg  [63:0] py_q$d;
    wire  [63:0] py_q$q;
    reg  py_q$clock;
    reg  front_top$clock;
    reg  [31:0] front_top$a;
    reg  [31:0] front_top$b;
    reg  [15:0] front_top$w;
    wire  [31:0] front_top$y;
    reg  front_bottom$clock;
    reg  [31:0] front_bottom$a;
    reg  [31:0] front_bottom$b;
    reg  [15:0] front_bottom$w;
    wire  [31:0] front_bottom$y;
    reg  front_y$clock;
    reg  [31:0] front_y$a;
    reg  [31:0] front_y$b;
    reg  [15:0] front_y$w;
    wire  [31:0] front_y$y;
    reg  back_top$clock;
    reg  [31:0] back_top$a;
    reg  [31:0] back_top$b;
    reg  [15:0] back_top$w;
    wire  [31:0] back_top$y;
    reg  back_bottom$clock;
    reg  [31:0] back_bottom$a;
    reg  [31:0] back_bottom$b;
    reg  [15:0] back_bottom$w;
    wire  [31:0] back_bottom$y;
    reg  back_y$clock;
    reg  [31:0] back_y$a;
    reg  [31:0] back_y$b;
    reg  [15:0] back_y$w;
    wire  [31:0] back_y$y;
    reg  [63:0] sat_x$v;
    wire  [31:0] sat_x$y;
    reg  [63:0] sat_y$v;
    wire  [31:0] sat_y$y;
    reg  [63:0] sat_z$v;
    wire  [31:0] sat_z$y;
    reg  [31:0] gx_out$d;
    wire  [31:0] gx_out$q;
    reg  gx_out$clock;
    reg  [31:0] gy_out$d;
    wire  [31:0] gy_out$q;
    reg  gy_out$clock;
    reg  [31:0] gz_out$d;
    wire  [31:0] gz_out$q;
    reg  gz_out$clock;
    reg  [31:0] centre_q$0$d;
    wire  [31:0] centre_q$0$q;
    reg  centre_q$0$clock;
    reg  [31:0] centre_q$1$d;
    wire  [31:0] centre_q$1$q;
    reg  centre_q$1$clock;
    reg  [31:0] centre_q$2$d;
    wire  [31:0] centre_q$2$q;
    reg  centre_q$2$clock;
    reg  [31:0] centre_q$3$d;
    wire  [31:0] centre_q$3$q;
    reg  centre_q$3$clock;
    reg  [31:0] centre_q$4$d;
    wire  [31:0] centre_q$4$q;
    reg  centre_q$4$clock;
    reg  [31:0] centre_q$5$d;
    wire  [31:0] centre_q$5$q;
    reg  centre_q$5$clock;
    reg  [31:0] centre_q$6$d;
    wire  [31:0] centre_q$6$q;
    reg  centre_q$6$clock;
    
    // Local signals
    reg  [63:0] shear_sum;
    reg  [63:0] shear;
    reg  sx_pos;
    reg  sx_neg;
    reg  sy_pos;
    reg  sy_neg;
    reg  [31:0] front_row$0;
    reg  [31:0] front_row$1;
    reg  [31:0] front_row$2;
    reg  [31:0] back_row$0;
    reg  [31:0] back_row$1;
    reg  [31:0] back_row$2;
    reg  [31:0] front_x;
    reg  [31:0] front_xy;
    reg  [31:0] back_x;
    reg  [31:0] back_xy;
    reg  [63:0] gr_wide;
    reg  [63:0] gz_wide;
    
    // Sub module instances
    top$pipeline$abc$estimators$3$b10x_q$0 b10x_q$0(
        .d(b10x_q$0$d),
        .q(b10x_q$0$q),
        .clock(b10x_q$0$clock)
    );
    top$pipeline$abc$estimators$3$b10x_q$1 b10x_q$1(
        .d(b10x_q$1$d),
        .q(b10x_q$1$q),
        .clock(b10x_q$1$clock)
    );
    top$pipeline$abc$estimators$3$b10y_q$0 b10y_q$0(
        .d(b10y_q$0$d),
        .q(b10y_q$0$q),
        .clock(b10y_q$0$clock)
    );
    top$pipeline$abc$estimators$3$b10y_q$1 b10y_q$1(
        .d(b10y_q$1$d),
        .q(b10y_q$1$q),
        .clock(b10y_q$1$clock)
    );
    top$pipeline$abc$estimators$3$b10z_q$0 b10z_q$0(
        .d(b10z_q$0$d),
        .q(b10z_q$0$q),
        .clock(b10z_q$0$clock)
    );
    top$pipeline$abc$estimators$3$b10z_q$1 b10z_q$1(
        .d(b10z_q$1$d),
        .q(b10z_q$1$q),
        .clock(b10z_q$1$clock)
    );
    top$pipeline$abc$estimators$3$gx_q$0 gx_q$0(
        .d(gx_q$0$d),
        .q(gx_q$0$q),
        .clock(gx_q$0$clock)
    );
    top$pipeline$abc$estimators$3$gx_q$1 gx_q$1(
        .d(gx_q$1$d),
        .q(gx_q$1$q),
        .clock(gx_q$1$clock)
    );
    top$pipeline$abc$estimators$3$gx_q$2 gx_q$2(
        .d(gx_q$2$d),
        .q(gx_q$2$q),
        .clock(gx_q$2$clock)
    );
    top$pipeline$abc$estimators$3$gx_q$3 gx_q$3(
        .d(gx_q$3$d),
        .q(gx_q$3$q),
        .clock(gx_q$3$clock)
    );
    top$pipeline$abc$estimators$3$gx_q$4 gx_q$4(
        .d(gx_q$4$d),
        .q(gx_q$4$q),
        .clock(gx_q$4$clock)
    );
    top$pipeline$abc$estimators$3$gx_q$5 gx_q$5(
        .d(gx_q$5$d),
        .q(gx_q$5$q),
        .clock(gx_q$5$clock)
    );
    top$pipeline$abc$estimators$3$gy_q$0 gy_q$0(
        .d(gy_q$0$d),
        .q(gy_q$0$q),
        .clock(gy_q$0$clock)
    );
    top$pipeline$abc$estimators$3$gy_q$1 gy_q$1(
        .d(gy_q$1$d),
        .q(gy_q$1$q),
        .clock(gy_q$1$clock)
    );
    top$pipeline$abc$estimators$3$gy_q$2 gy_q$2(
        .d(gy_q$2$d),
        .q(gy_q$2$q),
        .clock(gy_q$2$clock)
    );
    top$pipeline$abc$estimators$3$gy_q$3 gy_q$3(
        .d(gy_q$3$d),
        .q(gy_q$3$q),
        .clock(gy_q$3$clock)
    );
    top$pipeline$abc$estimators$3$gy_q$4 gy_q$4(
        .d(gy_q$4$d),
        .q(gy_q$4$q),
        .clock(gy_q$4$clock)
    );
    top$pipeline$abc$estimators$3$gy_q$5 gy_q$5(
        .d(gy_q$5$d),
        .q(gy_q$5$q),
        .clock(gy_q$5$clock)
    );
    top$pipeline$abc$estimators$3$gr_q$0 gr_q$0(
        .d(gr_q$0$d),
        .q(gr_q$0$q),
        .clock(gr_q$0$clock)
    );
    top$pipeline$abc$estimators$3$gr_q$1 gr_q$1(
        .d(gr_q$1$d),
        .q(gr_q$1$q),
        .clock(gr_q$1$clock)
    );
    top$pipeline$abc$estimators$3$gr_q$2 gr_q$2(
        .d(gr_q$2$d),
        .q(gr_q$2$q),
        .clock(gr_q$2$clock)
    );
    top$pipeline$abc$estimators$3$gr_q$3 gr_q$3(
        .d(gr_q$3$d),
        .q(gr_q$3$q),
        .clock(gr_q$3$clock)
    );
    top$pipeline$abc$estimators$3$gr_q$4 gr_q$4(
        .d(gr_q$4$d),
        .q(gr_q$4$q),
        .clock(gr_q$4$clock)
    );
    top$pipeline$abc$estimators$3$gr_q$5 gr_q$5(
        .d(gr_q$5$d),
        .q(gr_q$5$q),
        .clock(gr_q$5$clock)
    );
    top$pipeline$abc$estimators$3$dx_neg_q$0 dx_neg_q$0(
        .d(dx_neg_q$0$d),
        .q(dx_neg_q$0$q),
        .clock(dx_neg_q$0$clock)
    );
    top$pipeline$abc$estimators$3$dx_neg_q$1 dx_neg_q$1(
        .d(dx_neg_q$1$d),
        .q(dx_neg_q$1$q),
        .clock(dx_neg_q$1$clock)
    );
    top$pipeline$abc$estimators$3$dx_neg_q$2 dx_neg_q$2(
        .d(dx_neg_q$2$d),
        .q(dx_neg_q$2$q),
        .clock(dx_neg_q$2$clock)
    );
    top$pipeline$abc$estimators$3$dx_neg_q$3 dx_neg_q$3(
        .d(dx_neg_q$3$d),
        .q(dx_neg_q$3$q),
        .clock(dx_neg_q$3$clock)
    );
    top$pipeline$abc$estimators$3$dx_neg_q$4 dx_neg_q$4(
        .d(dx_neg_q$4$d),
        .q(dx_neg_q$4$q),
        .clock(dx_neg_q$4$clock)
    );
    top$pipeline$abc$estimators$3$dx_mag_q$0 dx_mag_q$0(
        .d(dx_mag_q$0$d),
        .q(dx_mag_q$0$q),
        .clock(dx_mag_q$0$clock)
    );
    top$pipeline$abc$estimators$3$dx_mag_q$1 dx_mag_q$1(
        .d(dx_mag_q$1$d),
        .q(dx_mag_q$1$q),
        .clock(dx_mag_q$1$clock)
    );
    top$pipeline$abc$estimators$3$dx_mag_q$2 dx_mag_q$2(
        .d(dx_mag_q$2$d),
        .q(dx_mag_q$2$q),
        .clock(dx_mag_q$2$clock)
    );
    top$pipeline$abc$estimators$3$dx_mag_q$3 dx_mag_q$3(
        .d(dx_mag_q$3$d),
        .q(dx_mag_q$3$q),
        .clock(dx_mag_q$3$clock)
    );
    top$pipeline$abc$estimators$3$dx_mag_q$4 dx_mag_q$4(
        .d(dx_mag_q$4$d),
        .q(dx_mag_q$4$q),
        .clock(dx_mag_q$4$clock)
    );
    top$pipeline$abc$estimators$3$dy_neg_q$0 dy_neg_q$0(
        .d(dy_neg_q$0$d),
        .q(dy_neg_q$0$q),
        .clock(dy_neg_q$0$clock)
    );
    top$pipeline$abc$estimators$3$dy_neg_q$1 dy_neg_q$1(
        .d(dy_neg_q$1$d),
        .q(dy_neg_q$1$q),
        .clock(dy_neg_q$1$clock)
    );
    top$pipeline$abc$estimators$3$dy_neg_q$2 dy_neg_q$2(
        .d(dy_neg_q$2$d),
        .q(dy_neg_q$2$q),
        .clock(dy_neg_q$2$clock)
    );
    top$pipeline$abc$estimators$3$dy_neg_q$3 dy_neg_q$3(
        .d(dy_neg_q$3$d),
        .q(dy_neg_q$3$q),
        .clock(dy_neg_q$3$clock)
    );
    top$pipeline$abc$estimators$3$dy_neg_q$4 dy_neg_q$4(
        .d(dy_neg_q$4$d),
        .q(dy_neg_q$4$q),
        .clock(dy_neg_q$4$clock)
    );
    top$pipeline$abc$estimators$3$dy_mag_q$0 dy_mag_q$0(
        .d(dy_mag_q$0$d),
        .q(dy_mag_q$0$q),
        .clock(dy_mag_q$0$clock)
    );
    top$pipeline$abc$estimators$3$dy_mag_q$1 dy_mag_q$1(
        .d(dy_mag_q$1$d),
        .q(dy_mag_q$1$q),
        .clock(dy_mag_q$1$clock)
    );
    top$pipeline$abc$estimators$3$dy_mag_q$2 dy_mag_q$2(
        .d(dy_mag_q$2$d),
        .q(dy_mag_q$2$q),
        .clock(dy_mag_q$2$clock)
    );
    top$pipeline$abc$estimators$3$dy_mag_q$3 dy_mag_q$3(
        .d(dy_mag_q$3$d),
        .q(dy_mag_q$3$q),
        .clock(dy_mag_q$3$clock)
    );
    top$pipeline$abc$estimators$3$dy_mag_q$4 dy_mag_q$4(
        .d(dy_mag_q$4$d),
        .q(dy_mag_q$4$q),
        .clock(dy_mag_q$4$clock)
    );
    top$pipeline$abc$estimators$3$px px(
        .g(px$g),
        .d_neg(px$d_neg),
        .d_mag(px$d_mag),
        .y(px$y)
    );
    top$pipeline$abc$estimators$3$py py(
        .g(py$g),
        .d_neg(py$d_neg),
        .d_mag(py$d_mag),
        .y(py$y)
    );
    top$pipeline$abc$estimators$3$px_q px_q(
        .d(px_q$d),
        .q(px_q$q),
        .clock(px_q$clock)
    );
    top$pipeline$abc$estimators$3$py_q py_q(
        .d(py_q$d),
        .q(py_q$q),
        .clock(py_q$clock)
    );
    top$pipeline$abc$estimators$3$front_top front_top(
        .clock(front_top$clock),
        .a(front_top$a),
        .b(front_top$b),
        .w(front_top$w),
        .y(front_top$y)
    );
    top$pipeline$abc$estimators$3$front_bottom front_bottom(
        .clock(front_bottom$clock),
        .a(front_bottom$a),
        .b(front_bottom$b),
        .w(front_bottom$w),
        .y(front_bottom$y)
    );
    top$pipeline$abc$estimators$3$front_y front_y(
        .clock(front_y$clock),
        .a(front_y$a),
        .b(front_y$b),
        .w(front_y$w),
        .y(front_y$y)
    );
    top$pipeline$abc$estimators$3$back_top back_top(
        .clock(back_top$clock),
        .a(back_top$a),
        .b(back_top$b),
        .w(back_top$w),
        .y(back_top$y)
    );
    top$pipeline$abc$estimators$3$back_bottom back_bottom(
        .clock(back_bottom$clock),
        .a(back_bottom$a),
        .b(back_bottom$b),
        .w(back_bottom$w),
        .y(back_bottom$y)
    );
    top$pipeline$abc$estimators$3$back_y back_y(
        .clock(back_y$clock),
        .a(back_y$a),
        .b(back_y$b),
        .w(back_y$w),
        .y(back_y$y)
    );
    top$pipeline$abc$estimators$3$sat_x sat_x(
        .v(sat_x$v),
        .y(sat_x$y)
    );
    top$pipeline$abc$estimators$3$sat_y sat_y(
        .v(sat_y$v),
        .y(sat_y$y)
    );
    top$pipeline$abc$estimators$3$sat_z sat_z(
        .v(sat_z$v),
        .y(sat_z$y)
    );
    top$pipeline$abc$estimators$3$gx_out gx_out(
        .d(gx_out$d),
        .q(gx_out$q),
        .clock(gx_out$clock)
    );
    top$pipeline$abc$estimators$3$gy_out gy_out(
        .d(gy_out$d),
        .q(gy_out$q),
        .clock(gy_out$clock)
    );
    top$pipeline$abc$estimators$3$gz_out gz_out(
        .d(gz_out$d),
        .q(gz_out$q),
        .clock(gz_out$clock)
    );
    top$pipeline$abc$estimators$3$centre_q$0 centre_q$0(
        .d(centre_q$0$d),
        .q(centre_q$0$q),
        .clock(centre_q$0$clock)
    );
    top$pipeline$abc$estimators$3$centre_q$1 centre_q$1(
        .d(centre_q$1$d),
        .q(centre_q$1$q),
        .clock(centre_q$1$clock)
    );
    top$pipeline$abc$estimators$3$centre_q$2 centre_q$2(
        .d(centre_q$2$d),
        .q(centre_q$2$q),
        .clock(centre_q$2$clock)
    );
    top$pipeline$abc$estimators$3$centre_q$3 centre_q$3(
        .d(centre_q$3$d),
        .q(centre_q$3$q),
        .clock(centre_q$3$clock)
    );
    top$pipeline$abc$estimators$3$centre_q$4 centre_q$4(
        .d(centre_q$4$d),
        .q(centre_q$4$q),
        .clock(centre_q$4$clock)
    );
    top$pipeline$abc$estimators$3$centre_q$5 centre_q$5(
        .d(centre_q$5$d),
        .q(centre_q$5$q),
        .clock(centre_q$5$clock)
    );
    top$pipeline$abc$estimators$3$centre_q$6 centre_q$6(
        .d(centre_q$6$d),
        .q(centre_q$6$q),
        .clock(centre_q$6$clock)
    );
    
    // Update code
    always @(*) begin
        px_q$clock = clock;
        py_q$clock = clock;
        gx_out$clock = clock;
        gy_out$clock = clock;
        gz_out$clock = clock;
        px_q$d = px_q$q;
        py_q$d = py_q$q;
        gx_out$d = gx_out$q;
        gy_out$d = gy_out$q;
        gz_out$d = gz_out$q;
        centre_q$0$clock = clock;
        centre_q$1$clock = clock;
        centre_q$2$clock = clock;
        centre_q$3$clock = clock;
        centre_q$4$clock = clock;
        centre_q$5$clock = clock;
        centre_q$6$clock = clock;
        centre_q$0$d = centre;
        centre_q$1$d = centre_q$0$q;
        centre_q$2$d = centre_q$1$q;
        centre_q$3$d = centre_q$2$q;
        centre_q$4$d = centre_q$3$q;
        centre_q$5$d = centre_q$4$q;
        centre_q$6$d = centre_q$5$q;
        sample = centre_q$6$q;
        gx_q$0$clock = clock;
        gy_q$0$clock = clock;
        gr_q$0$clock = clock;
        gx_q$1$clock = clock;
        gy_q$1$clock = clock;
        gr_q$1$clock = clock;
        gx_q$2$clock = clock;
        gy_q$2$clock = clock;
        gr_q$2$clock = clock;
        gx_q$3$clock = clock;
        gy_q$3$clock = clock;
        gr_q$3$clock = clock;
        gx_q$4$clock = clock;
        gy_q$4$clock = clock;
        gr_q$4$clock = clock;
        gx_q$5$clock = clock;
        gy_q$5$clock = clock;
        gr_q$5$clock = clock;
        b10x_q$0$clock = clock;
        b10y_q$0$clock = clock;
        b10z_q$0$clock = clock;
        b10x_q$1$clock = clock;
        b10y_q$1$clock = clock;
        b10z_q$1$clock = clock;
        dx_neg_q$0$clock = clock;
        dx_mag_q$0$clock = clock;
        dy_neg_q$0$clock = clock;
        dy_mag_q$0$clock = clock;
        dx_neg_q$1$clock = clock;
        dx_mag_q$1$clock = clock;
        dy_neg_q$1$clock = clock;
        dy_mag_q$1$clock = clock;
        dx_neg_q$2$clock = clock;
        dx_mag_q$2$clock = clock;
        dy_neg_q$2$clock = clock;
        dy_mag_q$2$clock = clock;
        dx_neg_q$3$clock = clock;
        dx_mag_q$3$clock = clock;
        dy_neg_q$3$clock = clock;
        dy_mag_q$3$clock = clock;
        dx_neg_q$4$clock = clock;
        dx_mag_q$4$clock = clock;
        dy_neg_q$4$clock = clock;
        dy_mag_q$4$clock = clock;
        front_top$clock = clock;
        front_bottom$clock = clock;
        front_y$clock = clock;
        back_top$clock = clock;
        back_bottom$clock = clock;
        back_y$clock = clock;
        gx_q$0$d = xp - xm;
        gy_q$0$d = yp - ym;
        gr_q$0$d = kp4 - km4;
        gx_q$1$d = gx_q$0$q;
        gy_q$1$d = gy_q$0$q;
        gr_q$1$d = gr_q$0$q;
        gx_q$2$d = gx_q$1$q;
        gy_q$2$d = gy_q$1$q;
        gr_q$2$d = gr_q$1$q;
        gx_q$3$d = gx_q$2$q;
        gy_q$3$d = gy_q$2$q;
        gr_q$3$d = gr_q$2$q;
        gx_q$4$d = gx_q$3$q;
        gy_q$4$d = gy_q$3$q;
        gr_q$4$d = gr_q$3$q;
        gx_q$5$d = gx_q$4$q;
        gy_q$5$d = gy_q$4$q;
        gr_q$5$d = gr_q$4$q;
        sums26$clock = clock;
        sums26$xp = xp;
        sums26$xm = xm;
        sums26$yp = yp;
        sums26$ym = ym;
        sums26$c0 = c0;
        sums26$c2 = c2;
        sums26$c6 = c6;
        sums26$c8 = c8;
        sums26$kp0 = kp0;
        sums26$kp1 = kp1;
        sums26$kp2 = kp2;
        sums26$kp3 = kp3;
        sums26$kp4 = kp4;
        sums26$kp5 = kp5;
        sums26$kp6 = kp6;
        sums26$kp7 = kp7;
        sums26$kp8 = kp8;
        sums26$km0 = km0;
        sums26$km1 = km1;
        sums26$km2 = km2;
        sums26$km3 = km3;
        sums26$km4 = km4;
        sums26$km5 = km5;
        sums26$km6 = km6;
        sums26$km7 = km7;
        sums26$km8 = km8;
        basis10$clock = clock;
        basis10$xp = xp;
        basis10$xm = xm;
        basis10$yp = yp;
        basis10$ym = ym;
        basis10$kp1 = kp1;
        basis10$kp3 = kp3;
        basis10$kp4 = kp4;
        basis10$kp5 = kp5;
        basis10$kp7 = kp7;
        basis10$km1 = km1;
        basis10$km3 = km3;
        basis10$km4 = km4;
        basis10$km5 = km5;
        basis10$km7 = km7;
        basis10$dx_neg = dx_neg;
        basis10$dx_mag = dx_mag;
        basis10$dy_neg = dy_neg;
        basis10$dy_mag = dy_mag;
        basis10$weights = weights10;
        basis10$basis_x = basis10_x;
        basis10$basis_y = basis10_y;
        basis10$basis_z = basis10_z;
        if (n26) begin
            gx_q$2$d = sums26$gx;
            gy_q$2$d = sums26$gy;
            gr_q$2$d = sums26$gr;
        end
        dx_neg_q$0$d = dx_neg;
        dx_mag_q$0$d = dx_mag;
        dy_neg_q$0$d = dy_neg;
        dy_mag_q$0$d = dy_mag;
        dx_neg_q$1$d = dx_neg_q$0$q;
        dx_mag_q$1$d = dx_mag_q$0$q;
        dy_neg_q$1$d = dy_neg_q$0$q;
        dy_mag_q$1$d = dy_mag_q$0$q;
        dx_neg_q$2$d = dx_neg_q$1$q;
        dx_mag_q$2$d = dx_mag_q$1$q;
        dy_neg_q$2$d = dy_neg_q$1$q;
        dy_mag_q$2$d = dy_mag_q$1$q;
        dx_neg_q$3$d = dx_neg_q$2$q;
        dx_mag_q$3$d = dx_mag_q$2$q;
        dy_neg_q$3$d = dy_neg_q$2$q;
        dy_mag_q$3$d = dy_mag_q$2$q;
        dx_neg_q$4$d = dx_neg_q$3$q;
        dx_mag_q$4$d = dx_mag_q$3$q;
        dy_neg_q$4$d = dy_neg_q$3$q;
        dy_mag_q$4$d = dy_mag_q$3$q;
        px$g = gx_q$4$q;
        px$d_neg = dx_neg_q$4$q;
        px$d_mag = dx_mag_q$4$q;
        py$g = gy_q$4$q;
        py$d_neg = dy_neg_q$4$q;
        py$d_mag = dy_mag_q$4$q;
        px_q$d = px$y;
        py_q$d = py$y;
        shear_sum = px_q$q + py_q$q + half;
        shear = shear_sum >> shift;
        if (shear_sum['h3f]) begin
            shear = ~((~shear_sum) >> shift);
        end
        sx_pos = ~dx_neg & |dx_mag;
        sx_neg = dx_neg & |dx_mag;
        sy_pos = ~dy_neg & |dy_mag;
        sy_neg = dy_neg & |dy_mag;
        front_row$0 = kp3;
        back_row$0 = km3;
        if (sy_pos) begin
            front_row$0 = kp6;
            back_row$0 = km0;
        end
        if (sy_neg) begin
            front_row$0 = kp0;
            back_row$0 = km6;
        end
        front_row$1 = kp4;
        back_row$1 = km4;
        if (sy_pos) begin
            front_row$1 = kp7;
            back_row$1 = km1;
        end
        if (sy_neg) begin
            front_row$1 = kp1;
            back_row$1 = km7;
        end
        front_row$2 = kp5;
        back_row$2 = km5;
        if (sy_pos) begin
            front_row$2 = kp8;
            back_row$2 = km2;
        end
        if (sy_neg) begin
            front_row$2 = kp2;
            back_row$2 = km8;
        end
        front_x = kp4;
        front_xy = front_row$1;
        back_x = km4;
        back_xy = back_row$1;
        if (sx_pos) begin
            front_x = kp5;
            front_xy = front_row$2;
            back_x = km3;
            back_xy = back_row$0;
        end
        if (sx_neg) begin
            front_x = kp3;
            front_xy = front_row$0;
            back_x = km5;
            back_xy = back_row$2;
        end
        front_top$a = kp4;
        front_top$b = front_x;
        front_top$w = dx_mag;
        front_bottom$a = front_row$1;
        front_bottom$b = front_xy;
        front_bottom$w = dx_mag;
        front_y$a = front_top$y;
        front_y$b = front_bottom$y;
        front_y$w = dy_mag_q$2$q;
        back_top$a = km4;
        back_top$b = back_x;
        back_top$w = dx_mag;
        back_bottom$a = back_row$1;
        back_bottom$b = back_xy;
        back_bottom$w = dx_mag;
        back_y$a = back_top$y;
        back_y$b = back_bottom$y;
        back_y$w = dy_mag_q$2$q;
        gr_wide = 64'(gr_q$5$q);
        if (gr_q$5$q['h1f]) begin
            gr_wide = 64'(gr_q$5$q) | sign_ext;
        end
        gz_wide = gr_wide - shear;
        if (n12) begin
            gz_wide = 64'(front_y$y) - 64'(back_y$y);
        end
        sat_x$v = 64'(gx_q$5$q);
        if (gx_q$5$q['h1f]) begin
            sat_x$v = 64'(gx_q$5$q) | sign_ext;
        end
        sat_y$v = 64'(gy_q$5$q);
        if (gy_q$5$q['h1f]) begin
            sat_y$v = 64'(gy_q$5$q) | sign_ext;
        end
        sat_z$v = gz_wide;
        b10x_q$0$d = basis10$gx;
        b10y_q$0$d = basis10$gy;
        b10z_q$0$d = basis10$gz;
        b10x_q$1$d = b10x_q$0$q;
        b10y_q$1$d = b10y_q$0$q;
        b10z_q$1$d = b10z_q$0$q;
        if (n10) begin
            sat_x$v = b10x_q$1$q;
            sat_y$v = b10y_q$1$q;
            sat_z$v = b10z_q$1$q;
        end
        gx_out$d = sat_x$y;
        gy_out$d = sat_y$y;
        gz_out$d = sat_z$y;
        gx = gx_out$q;
        gy = gy_out$q;
        gz = gz_out$q;
    end
    
endmodule // top$pipeline$abc$estimators$3
module top$pipeline$abc$estimators$3$b10x_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$b10x_q$0
module top$pipeline$abc$estimators$3$b10x_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$b10x_q$1
module top$pipeline$abc$estimators$3$b10y_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$b10y_q$0
module top$pipeline$abc$estimators$3$b10y_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$b10y_q$1
module top$pipeline$abc$estimators$3$b10z_q$0(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$b10z_q$0
module top$pipeline$abc$estimators$3$b10z_q$1(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$b10z_q$1
module top$pipeline$abc$estimators$3$back_bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$3$back_bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$3$back_bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$3$back_bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$3$back_bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$3$back_bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$3$back_bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$3$back_bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$3$back_bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$3$back_bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$3$back_bottom
module top$pipeline$abc$estimators$3$back_bottom$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_bottom$a_q
module top$pipeline$abc$estimators$3$back_bottom$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_bottom$a_q2
module top$pipeline$abc$estimators$3$back_bottom$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_bottom$diff_q
module top$pipeline$abc$estimators$3$back_bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$3$back_bottom$narrow
module top$pipeline$abc$estimators$3$back_bottom$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_bottom$prod_q
module top$pipeline$abc$estimators$3$back_bottom$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_bottom$up_q
module top$pipeline$abc$estimators$3$back_bottom$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_bottom$up_q2
module top$pipeline$abc$estimators$3$back_bottom$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_bottom$w_q
module top$pipeline$abc$estimators$3$back_bottom$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_bottom$y_q
module top$pipeline$abc$estimators$3$back_top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$3$back_top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$3$back_top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$3$back_top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$3$back_top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$3$back_top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$3$back_top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$3$back_top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$3$back_top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$3$back_top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$3$back_top
module top$pipeline$abc$estimators$3$back_top$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_top$a_q
module top$pipeline$abc$estimators$3$back_top$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_top$a_q2
module top$pipeline$abc$estimators$3$back_top$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_top$diff_q
module top$pipeline$abc$estimators$3$back_top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$3$back_top$narrow
module top$pipeline$abc$estimators$3$back_top$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_top$prod_q
module top$pipeline$abc$estimators$3$back_top$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_top$up_q
module top$pipeline$abc$estimators$3$back_top$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_top$up_q2
module top$pipeline$abc$estimators$3$back_top$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_top$w_q
module top$pipeline$abc$estimators$3$back_top$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_top$y_q
module top$pipeline$abc$estimators$3$back_y(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$3$back_y$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$3$back_y$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$3$back_y$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$3$back_y$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$3$back_y$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$3$back_y$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$3$back_y$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$3$back_y$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$3$back_y$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$3$back_y
module top$pipeline$abc$estimators$3$back_y$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_y$a_q
module top$pipeline$abc$estimators$3$back_y$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_y$a_q2
module top$pipeline$abc$estimators$3$back_y$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_y$diff_q
module top$pipeline$abc$estimators$3$back_y$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$3$back_y$narrow
module top$pipeline$abc$estimators$3$back_y$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_y$prod_q
module top$pipeline$abc$estimators$3$back_y$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_y$up_q
module top$pipeline$abc$estimators$3$back_y$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_y$up_q2
module top$pipeline$abc$estimators$3$back_y$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_y$w_q
module top$pipeline$abc$estimators$3$back_y$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$back_y$y_q
module top$pipeline$abc$estimators$3$centre_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$centre_q$0
module top$pipeline$abc$estimators$3$centre_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$centre_q$1
module top$pipeline$abc$estimators$3$centre_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$centre_q$2
module top$pipeline$abc$estimators$3$centre_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$centre_q$3
module top$pipeline$abc$estimators$3$centre_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$centre_q$4
module top$pipeline$abc$estimators$3$centre_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$centre_q$5
module top$pipeline$abc$estimators$3$centre_q$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$centre_q$6
module top$pipeline$abc$estimators$3$dx_mag_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dx_mag_q$0
module top$pipeline$abc$estimators$3$dx_mag_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dx_mag_q$1
module top$pipeline$abc$estimators$3$dx_mag_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dx_mag_q$2
module top$pipeline$abc$estimators$3$dx_mag_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dx_mag_q$3
module top$pipeline$abc$estimators$3$dx_mag_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dx_mag_q$4
module top$pipeline$abc$estimators$3$dx_neg_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dx_neg_q$0
module top$pipeline$abc$estimators$3$dx_neg_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dx_neg_q$1
module top$pipeline$abc$estimators$3$dx_neg_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dx_neg_q$2
module top$pipeline$abc$estimators$3$dx_neg_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dx_neg_q$3
module top$pipeline$abc$estimators$3$dx_neg_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dx_neg_q$4
module top$pipeline$abc$estimators$3$dy_mag_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dy_mag_q$0
module top$pipeline$abc$estimators$3$dy_mag_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dy_mag_q$1
module top$pipeline$abc$estimators$3$dy_mag_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dy_mag_q$2
module top$pipeline$abc$estimators$3$dy_mag_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dy_mag_q$3
module top$pipeline$abc$estimators$3$dy_mag_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dy_mag_q$4
module top$pipeline$abc$estimators$3$dy_neg_q$0(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dy_neg_q$0
module top$pipeline$abc$estimators$3$dy_neg_q$1(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dy_neg_q$1
module top$pipeline$abc$estimators$3$dy_neg_q$2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dy_neg_q$2
module top$pipeline$abc$estimators$3$dy_neg_q$3(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dy_neg_q$3
module top$pipeline$abc$estimators$3$dy_neg_q$4(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$dy_neg_q$4
module top$pipeline$abc$estimators$3$front_bottom(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$3$front_bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$3$front_bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$3$front_bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$3$front_bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$3$front_bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$3$front_bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$3$front_bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$3$front_bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$3$front_bottom$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$3$front_bottom
module top$pipeline$abc$estimators$3$front_bottom$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_bottom$a_q
module top$pipeline$abc$estimators$3$front_bottom$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_bottom$a_q2
module top$pipeline$abc$estimators$3$front_bottom$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_bottom$diff_q
module top$pipeline$abc$estimators$3$front_bottom$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$3$front_bottom$narrow
module top$pipeline$abc$estimators$3$front_bottom$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_bottom$prod_q
module top$pipeline$abc$estimators$3$front_bottom$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_bottom$up_q
module top$pipeline$abc$estimators$3$front_bottom$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_bottom$up_q2
module top$pipeline$abc$estimators$3$front_bottom$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_bottom$w_q
module top$pipeline$abc$estimators$3$front_bottom$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_bottom$y_q
module top$pipeline$abc$estimators$3$front_top(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$3$front_top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$3$front_top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$3$front_top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$3$front_top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$3$front_top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$3$front_top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$3$front_top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$3$front_top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$3$front_top$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$3$front_top
module top$pipeline$abc$estimators$3$front_top$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_top$a_q
module top$pipeline$abc$estimators$3$front_top$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_top$a_q2
module top$pipeline$abc$estimators$3$front_top$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_top$diff_q
module top$pipeline$abc$estimators$3$front_top$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$3$front_top$narrow
module top$pipeline$abc$estimators$3$front_top$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_top$prod_q
module top$pipeline$abc$estimators$3$front_top$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_top$up_q
module top$pipeline$abc$estimators$3$front_top$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_top$up_q2
module top$pipeline$abc$estimators$3$front_top$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_top$w_q
module top$pipeline$abc$estimators$3$front_top$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_top$y_q
module top$pipeline$abc$estimators$3$front_y(clock,a,b,w,y);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] a;
    input wire  [31:0] b;
    input wire  [15:0] w;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  half = 64'h80;
    localparam  shift = 8'h8;
    localparam  wide = 1'b0;
    localparam  split = 1'b1;
    
    // Stub signals
    reg  up_q$d;
    wire  up_q$q;
    reg  up_q$clock;
    reg  [31:0] a_q$d;
    wire  [31:0] a_q$q;
    reg  a_q$clock;
    reg  [31:0] diff_q$d;
    wire  [31:0] diff_q$q;
    reg  diff_q$clock;
    reg  [15:0] w_q$d;
    wire  [15:0] w_q$q;
    reg  w_q$clock;
    reg  narrow$clock;
    reg  [15:0] narrow$a;
    reg  [15:0] narrow$b;
    wire  [31:0] narrow$p;
    reg  up_q2$d;
    wire  up_q2$q;
    reg  up_q2$clock;
    reg  [63:0] a_q2$d;
    wire  [63:0] a_q2$q;
    reg  a_q2$clock;
    reg  [63:0] prod_q$d;
    wire  [63:0] prod_q$q;
    reg  prod_q$clock;
    reg  [31:0] y_q$d;
    wire  [31:0] y_q$q;
    reg  y_q$clock;
    
    // Local signals
    reg  up_c;
    reg  [31:0] diff_c;
    reg  up;
    reg  [31:0] a_in;
    reg  [31:0] diff;
    reg  [15:0] w_in;
    reg  [63:0] prod;
    reg  [63:0] prod_r;
    reg  [63:0] sum;
    
    // Sub module instances
    top$pipeline$abc$estimators$3$front_y$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$abc$estimators$3$front_y$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$abc$estimators$3$front_y$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$abc$estimators$3$front_y$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$abc$estimators$3$front_y$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$abc$estimators$3$front_y$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$abc$estimators$3$front_y$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$abc$estimators$3$front_y$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$abc$estimators$3$front_y$y_q y_q(
        .d(y_q$d),
        .q(y_q$q),
        .clock(y_q$clock)
    );
    
    // Update code
    always @(*) begin
        up_q$clock = clock;
        a_q$clock = clock;
        diff_q$clock = clock;
        w_q$clock = clock;
        up_q2$clock = clock;
        a_q2$clock = clock;
        prod_q$clock = clock;
        y_q$clock = clock;
        up_q$d = up_q$q;
        a_q$d = a_q$q;
        diff_q$d = diff_q$q;
        w_q$d = w_q$q;
        up_q2$d = up_q2$q;
        a_q2$d = a_q2$q;
        prod_q$d = prod_q$q;
        y_q$d = y_q$q;
        up_c = b >= a;
        diff_c = b - a;
        if (~up_c) begin
            diff_c = a - b;
        end
        up_q$d = up_c;
        a_q$d = a;
        diff_q$d = diff_c;
        w_q$d = w;
        up = up_c;
        a_in = a;
        diff = diff_c;
        w_in = w;
        if (split) begin
            up = up_q$q;
            a_in = a_q$q;
            diff = diff_q$q;
            w_in = w_q$q;
        end
        narrow$clock = clock;
        narrow$a = diff[('h0)+:(16)];
        narrow$b = w_in;
        prod = 'h0;
        if (wide) begin
            prod = (64'(diff[('h10)+:(16)] * w_in) << 'h10) + 64'(diff[('h0)+:(16)] * w_in);
        end
        up_q2$d = up;
        a_q2$d = (64'(a_in) << shift) | half;
        prod_q$d = prod;
        prod_r = 64'(narrow$p);
        if (wide) begin
            prod_r = prod_q$q;
        end
        sum = a_q2$q - prod_r;
        if (up_q2$q) begin
            sum = a_q2$q + prod_r;
        end
        y_q$d = 32'(sum >> shift);
        y = y_q$q;
    end
    
endmodule // top$pipeline$abc$estimators$3$front_y
module top$pipeline$abc$estimators$3$front_y$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_y$a_q
module top$pipeline$abc$estimators$3$front_y$a_q2(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_y$a_q2
module top$pipeline$abc$estimators$3$front_y$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_y$diff_q
module top$pipeline$abc$estimators$3$front_y$narrow(clock,a,b,p);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [31:0] p;
    
    // Update code (custom)
    `ifdef CUBE_ECP5_DSP
    wire [35:0] product;
    MULT18X18D #(
       .REG_INPUTA_CLK("NONE"), .REG_INPUTB_CLK("NONE"), .REG_PIPELINE_CLK("NONE"),
       .REG_OUTPUT_CLK("CLK0"), .REG_OUTPUT_CE("CE0"), .REG_OUTPUT_RST("RST0")
    ) mult (
       .A0(a[0]), .A1(a[1]), .A2(a[2]), .A3(a[3]), .A4(a[4]), .A5(a[5]), .A6(a[6]), .A7(a[7]), .A8(a[8]), .A9(a[9]), .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]), .A15(a[15]), .A16(1'b0), .A17(1'b0),
       .B0(b[0]), .B1(b[1]), .B2(b[2]), .B3(b[3]), .B4(b[4]), .B5(b[5]), .B6(b[6]), .B7(b[7]), .B8(b[8]), .B9(b[9]), .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]), .B15(b[15]), .B16(1'b0), .B17(1'b0),
       .C0(1'b0), .C1(1'b0), .C2(1'b0), .C3(1'b0), .C4(1'b0), .C5(1'b0), .C6(1'b0), .C7(1'b0), .C8(1'b0), .C9(1'b0), .C10(1'b0), .C11(1'b0), .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
       .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
       .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
       .P0(product[0]), .P1(product[1]), .P2(product[2]), .P3(product[3]), .P4(product[4]), .P5(product[5]), .P6(product[6]), .P7(product[7]), .P8(product[8]), .P9(product[9]), .P10(product[10]), .P11(product[11]), .P12(product[12]), .P13(product[13]), .P14(product[14]), .P15(product[15]), .P16(product[16]), .P17(product[17]), .P18(product[18]), .P19(product[19]), .P20(product[20]), .P21(product[21]), .P22(product[22]), .P23(product[23]), .P24(product[24]), .P25(product[25]), .P26(product[26]), .P27(product[27]), .P28(product[28]), .P29(product[29]), .P30(product[30]), .P31(product[31]), .P32(product[32]), .P33(product[33]), .P34(product[34]), .P35(product[35])
    );
    always @(*) begin
       p = product[31:0];
    end
    `else
    initial begin
       p = 'h0;
    end
    
    always @(posedge clock) begin
       p <= a * b;
    end
    `endif
endmodule // top$pipeline$abc$estimators$3$front_y$narrow
module top$pipeline$abc$estimators$3$front_y$prod_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_y$prod_q
module top$pipeline$abc$estimators$3$front_y$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_y$up_q
module top$pipeline$abc$estimators$3$front_y$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_y$up_q2
module top$pipeline$abc$estimators$3$front_y$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_y$w_q
module top$pipeline$abc$estimators$3$front_y$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$front_y$y_q
module top$pipeline$abc$estimators$3$gr_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gr_q$0
module top$pipeline$abc$estimators$3$gr_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gr_q$1
module top$pipeline$abc$estimators$3$gr_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gr_q$2
module top$pipeline$abc$estimators$3$gr_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gr_q$3
module top$pipeline$abc$estimators$3$gr_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gr_q$4
module top$pipeline$abc$estimators$3$gr_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gr_q$5
module top$pipeline$abc$estimators$3$gx_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gx_out
module top$pipeline$abc$estimators$3$gx_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gx_q$0
module top$pipeline$abc$estimators$3$gx_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gx_q$1
module top$pipeline$abc$estimators$3$gx_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gx_q$2
module top$pipeline$abc$estimators$3$gx_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gx_q$3
module top$pipeline$abc$estimators$3$gx_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gx_q$4
module top$pipeline$abc$estimators$3$gx_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gx_q$5
module top$pipeline$abc$estimators$3$gy_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gy_out
module top$pipeline$abc$estimators$3$gy_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gy_q$0
module top$pipeline$abc$estimators$3$gy_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gy_q$1
module top$pipeline$abc$estimators$3$gy_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gy_q$2
module top$pipeline$abc$estimators$3$gy_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gy_q$3
module top$pipeline$abc$estimators$3$gy_q$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gy_q$4
module top$pipeline$abc$estimators$3$gy_q$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gy_q$5
module top$pipeline$abc$estimators$3$gz_out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$gz_out
module top$pipeline$abc$estimators$3$px(g,d_neg,d_mag,y);
    
    // Module arguments
    input wire  [31:0] g;
    input wire  d_neg;
    input wire  [15:0] d_mag;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] mag;
    reg  [63:0] prod;
    
    // Update code
    reg  [63:0] y_pass;
    always @(*) begin
        mag = g;
        if (g['h1f]) begin
            mag = ~g + 'h1;
        end
        prod = 64'(mag[('h0)+:(16)] * d_mag);
        if (wide) begin
            prod = (64'(mag[('h10)+:(16)] * d_mag) << 'h10) + 64'(mag[('h0)+:(16)] * d_mag);
        end
        y_pass = prod;
        if (g['h1f] ^ d_neg) begin
            y_pass = ~prod + 'h1;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$3$px
module top$pipeline$abc$estimators$3$px_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$px_q
module top$pipeline$abc$estimators$3$py(g,d_neg,d_mag,y);
    
    // Module arguments
    input wire  [31:0] g;
    input wire  d_neg;
    input wire  [15:0] d_mag;
    output reg  [63:0] y;
    
    // Constant declarations
    localparam  wide = 1'b0;
    
    // Local signals
    reg  [31:0] mag;
    reg  [63:0] prod;
    
    // Update code
    reg  [63:0] y_pass;
    always @(*) begin
        mag = g;
        if (g['h1f]) begin
            mag = ~g + 'h1;
        end
        prod = 64'(mag[('h0)+:(16)] * d_mag);
        if (wide) begin
            prod = (64'(mag[('h10)+:(16)] * d_mag) << 'h10) + 64'(mag[('h0)+:(16)] * d_mag);
        end
        y_pass = prod;
        if (g['h1f] ^ d_neg) begin
            y_pass = ~prod + 'h1;
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$3$py
module top$pipeline$abc$estimators$3$py_q(d,q,clock);
    
    // Module arguments
    input wire  [63:0] d;
    output reg  [63:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$estimators$3$py_q
module top$pipeline$abc$estimators$3$sat_x(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$3$sat_x
module top$pipeline$abc$estimators$3$sat_y(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$3$sat_y
module top$pipeline$abc$estimators$3$sat_z(v,y);
    
    // Module arguments
    input wire  [63:0] v;
    output reg  [31:0] y;
    
    // Constant declarations
    localparam  lim = 64'h3fff;
    localparam  high = 'h3fff;
    localparam  low = 'hffffc001;
    
    // Local signals
    reg  [63:0] mag;
    
    // Update code
    reg  [31:0] y_pass;
    always @(*) begin
        mag = v;
        if (v['h3f]) begin
            mag = ~v + 'h1;
        end
        y_pass = v[('h0)+:(32)];
        if (mag > lim) begin
            y_pass = high;
            if (v['h3f]) begin
                y_pass = low;
            end
        end
        y = y_pass;
    end
    
endmodule // top$pipeline$abc$estimators$3$sat_z
module top$pipeline$abc$lanes$0(clock,ray_last,line_last,sample,t000,t001,t002,t010,t011,t012,t020,t021,t022,t100,t101,t102,t110,t111,t112,t120,t121,t122,t200,t201,t202,t210,t211,t212,t220,t221,t222);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] ray_last;
    input wire  [15:0] line_last;
    input wire  [31:0] sample;
    output reg  [31:0] t000;
    output reg  [31:0] t001;
    output reg  [31:0] t002;
    output reg  [31:0] t010;
    output reg  [31:0] t011;
    output reg  [31:0] t012;
    output reg  [31:0] t020;
    output reg  [31:0] t021;
    output reg  [31:0] t022;
    output reg  [31:0] t100;
    output reg  [31:0] t101;
    output reg  [31:0] t102;
    output reg  [31:0] t110;
    output reg  [31:0] t111;
    output reg  [31:0] t112;
    output reg  [31:0] t120;
    output reg  [31:0] t121;
    output reg  [31:0] t122;
    output reg  [31:0] t200;
    output reg  [31:0] t201;
    output reg  [31:0] t202;
    output reg  [31:0] t210;
    output reg  [31:0] t211;
    output reg  [31:0] t212;
    output reg  [31:0] t220;
    output reg  [31:0] t221;
    output reg  [31:0] t222;
    
    // Constant declarations
    localparam  long$0 = 1'b0;
    localparam  long$1 = 1'b0;
    localparam  long$2 = 1'b1;
    localparam  long$3 = 1'b0;
    localparam  long$4 = 1'b0;
    localparam  long$5 = 1'b1;
    localparam  long$6 = 1'b0;
    localparam  long$7 = 1'b0;
    
    // Stub signals
    reg  [31:0] one$0$d;
    wire  [31:0] one$0$q;
    reg  one$0$clock;
    reg  [31:0] one$1$d;
    wire  [31:0] one$1$q;
    reg  one$1$clock;
    reg  [31:0] one$2$d;
    wire  [31:0] one$2$q;
    reg  one$2$clock;
    reg  [31:0] one$3$d;
    wire  [31:0] one$3$q;
    reg  one$3$clock;
    reg  [31:0] one$4$d;
    wire  [31:0] one$4$q;
    reg  one$4$clock;
    reg  [31:0] one$5$d;
    wire  [31:0] one$5$q;
    reg  one$5$clock;
    reg  [31:0] one$6$d;
    wire  [31:0] one$6$q;
    reg  one$6$clock;
    reg  [31:0] one$7$d;
    wire  [31:0] one$7$q;
    reg  one$7$clock;
    reg  [31:0] one$8$d;
    wire  [31:0] one$8$q;
    reg  one$8$clock;
    reg  [31:0] two$0$d;
    wire  [31:0] two$0$q;
    reg  two$0$clock;
    reg  [31:0] two$1$d;
    wire  [31:0] two$1$q;
    reg  two$1$clock;
    reg  [31:0] two$2$d;
    wire  [31:0] two$2$q;
    reg  two$2$clock;
    reg  [31:0] two$3$d;
    wire  [31:0] two$3$q;
    reg  two$3$clock;
    reg  [31:0] two$4$d;
    wire  [31:0] two$4$q;
    reg  two$4$clock;
    reg  [31:0] two$5$d;
    wire  [31:0] two$5$q;
    reg  two$5$clock;
    reg  [31:0] two$6$d;
    wire  [31:0] two$6$q;
    reg  two$6$clock;
    reg  [31:0] two$7$d;
    wire  [31:0] two$7$q;
    reg  two$7$clock;
    reg  [31:0] two$8$d;
    wire  [31:0] two$8$q;
    reg  two$8$clock;
    reg  lines$0$clock;
    reg  [31:0] lines$0$data_in;
    reg  lines$0$write_enable;
    wire  [31:0] lines$0$data_out;
    reg  [15:0] lines$0$last;
    reg  lines$1$clock;
    reg  [31:0] lines$1$data_in;
    reg  lines$1$write_enable;
    wire  [31:0] lines$1$data_out;
    reg  [15:0] lines$1$last;
    reg  lines$2$clock;
    reg  [31:0] lines$2$data_in;
    reg  lines$2$write_enable;
    wire  [31:0] lines$2$data_out;
    reg  [15:0] lines$2$last;
    reg  lines$3$clock;
    reg  [31:0] lines$3$data_in;
    reg  lines$3$write_enable;
    wire  [31:0] lines$3$data_out;
    reg  [15:0] lines$3$last;
    reg  lines$4$clock;
    reg  [31:0] lines$4$data_in;
    reg  lines$4$write_enable;
    wire  [31:0] lines$4$data_out;
    reg  [15:0] lines$4$last;
    reg  lines$5$clock;
    reg  [31:0] lines$5$data_in;
    reg  lines$5$write_enable;
    wire  [31:0] lines$5$data_out;
    reg  [15:0] lines$5$last;
    reg  lines$6$clock;
    reg  [31:0] lines$6$data_in;
    reg  lines$6$write_enable;
    wire  [31:0] lines$6$data_out;
    reg  [15:0] lines$6$last;
    reg  lines$7$clock;
    reg  [31:0] lines$7$data_in;
    reg  lines$7$write_enable;
    wire  [31:0] lines$7$data_out;
    reg  [15:0] lines$7$last;
    
    // Local signals
    reg  [31:0] head$0;
    reg  [31:0] head$1;
    reg  [31:0] head$2;
    reg  [31:0] head$3;
    reg  [31:0] head$4;
    reg  [31:0] head$5;
    reg  [31:0] head$6;
    reg  [31:0] head$7;
    reg  [31:0] head$8;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$one$0 one$0(
        .d(one$0$d),
        .q(one$0$q),
        .clock(one$0$clock)
    );
    top$pipeline$abc$lanes$0$one$1 one$1(
        .d(one$1$d),
        .q(one$1$q),
        .clock(one$1$clock)
    );
    top$pipeline$abc$lanes$0$one$2 one$2(
        .d(one$2$d),
        .q(one$2$q),
        .clock(one$2$clock)
    );
    top$pipeline$abc$lanes$0$one$3 one$3(
        .d(one$3$d),
        .q(one$3$q),
        .clock(one$3$clock)
    );
    top$pipeline$abc$lanes$0$one$4 one$4(
        .d(one$4$d),
        .q(one$4$q),
        .clock(one$4$clock)
    );
    top$pipeline$abc$lanes$0$one$5 one$5(
        .d(one$5$d),
        .q(one$5$q),
        .clock(one$5$clock)
    );
    top$pipeline$abc$lanes$0$one$6 one$6(
        .d(one$6$d),
        .q(one$6$q),
        .clock(one$6$clock)
    );
    top$pipeline$abc$lanes$0$one$7 one$7(
        .d(one$7$d),
        .q(one$7$q),
        .clock(one$7$clock)
    );
    top$pipeline$abc$lanes$0$one$8 one$8(
        .d(one$8$d),
        .q(one$8$q),
        .clock(one$8$clock)
    );
    top$pipeline$abc$lanes$0$two$0 two$0(
        .d(two$0$d),
        .q(two$0$q),
        .clock(two$0$clock)
    );
    top$pipeline$abc$lanes$0$two$1 two$1(
        .d(two$1$d),
        .q(two$1$q),
        .clock(two$1$clock)
    );
    top$pipeline$abc$lanes$0$two$2 two$2(
        .d(two$2$d),
        .q(two$2$q),
        .clock(two$2$clock)
    );
    top$pipeline$abc$lanes$0$two$3 two$3(
        .d(two$3$d),
        .q(two$3$q),
        .clock(two$3$clock)
    );
    top$pipeline$abc$lanes$0$two$4 two$4(
        .d(two$4$d),
        .q(two$4$q),
        .clock(two$4$clock)
    );
    top$pipeline$abc$lanes$0$two$5 two$5(
        .d(two$5$d),
        .q(two$5$q),
        .clock(two$5$clock)
    );
    top$pipeline$abc$lanes$0$two$6 two$6(
        .d(two$6$d),
        .q(two$6$q),
        .clock(two$6$clock)
    );
    top$pipeline$abc$lanes$0$two$7 two$7(
        .d(two$7$d),
        .q(two$7$q),
        .clock(two$7$clock)
    );
    top$pipeline$abc$lanes$0$two$8 two$8(
        .d(two$8$d),
        .q(two$8$q),
        .clock(two$8$clock)
    );
    top$pipeline$abc$lanes$0$lines$0 lines$0(
        .clock(lines$0$clock),
        .data_in(lines$0$data_in),
        .write_enable(lines$0$write_enable),
        .data_out(lines$0$data_out),
        .last(lines$0$last)
    );
    top$pipeline$abc$lanes$0$lines$1 lines$1(
        .clock(lines$1$clock),
        .data_in(lines$1$data_in),
        .write_enable(lines$1$write_enable),
        .data_out(lines$1$data_out),
        .last(lines$1$last)
    );
    top$pipeline$abc$lanes$0$lines$2 lines$2(
        .clock(lines$2$clock),
        .data_in(lines$2$data_in),
        .write_enable(lines$2$write_enable),
        .data_out(lines$2$data_out),
        .last(lines$2$last)
    );
    top$pipeline$abc$lanes$0$lines$3 lines$3(
        .clock(lines$3$clock),
        .data_in(lines$3$data_in),
        .write_enable(lines$3$write_enable),
        .data_out(lines$3$data_out),
        .last(lines$3$last)
    );
    top$pipeline$abc$lanes$0$lines$4 lines$4(
        .clock(lines$4$clock),
        .data_in(lines$4$data_in),
        .write_enable(lines$4$write_enable),
        .data_out(lines$4$data_out),
        .last(lines$4$last)
    );
    top$pipeline$abc$lanes$0$lines$5 lines$5(
        .clock(lines$5$clock),
        .data_in(lines$5$data_in),
        .write_enable(lines$5$write_enable),
        .data_out(lines$5$data_out),
        .last(lines$5$last)
    );
    top$pipeline$abc$lanes$0$lines$6 lines$6(
        .clock(lines$6$clock),
        .data_in(lines$6$data_in),
        .write_enable(lines$6$write_enable),
        .data_out(lines$6$data_out),
        .last(lines$6$last)
    );
    top$pipeline$abc$lanes$0$lines$7 lines$7(
        .clock(lines$7$clock),
        .data_in(lines$7$data_in),
        .write_enable(lines$7$write_enable),
        .data_out(lines$7$data_out),
        .last(lines$7$last)
    );
    
    // Update code
    always @(*) begin
        head$0 = sample;
        lines$0$clock = clock;
        lines$0$last = ray_last;
        if (long$0) begin
            lines$0$last = line_last;
        end
        lines$0$write_enable = 1'b1;
        lines$0$data_in = two$0$q;
        head$1 = lines$0$data_out;
        lines$1$clock = clock;
        lines$1$last = ray_last;
        if (long$1) begin
            lines$1$last = line_last;
        end
        lines$1$write_enable = 1'b1;
        lines$1$data_in = two$1$q;
        head$2 = lines$1$data_out;
        lines$2$clock = clock;
        lines$2$last = ray_last;
        if (long$2) begin
            lines$2$last = line_last;
        end
        lines$2$write_enable = 1'b1;
        lines$2$data_in = two$2$q;
        head$3 = lines$2$data_out;
        lines$3$clock = clock;
        lines$3$last = ray_last;
        if (long$3) begin
            lines$3$last = line_last;
        end
        lines$3$write_enable = 1'b1;
        lines$3$data_in = two$3$q;
        head$4 = lines$3$data_out;
        lines$4$clock = clock;
        lines$4$last = ray_last;
        if (long$4) begin
            lines$4$last = line_last;
        end
        lines$4$write_enable = 1'b1;
        lines$4$data_in = two$4$q;
        head$5 = lines$4$data_out;
        lines$5$clock = clock;
        lines$5$last = ray_last;
        if (long$5) begin
            lines$5$last = line_last;
        end
        lines$5$write_enable = 1'b1;
        lines$5$data_in = two$5$q;
        head$6 = lines$5$data_out;
        lines$6$clock = clock;
        lines$6$last = ray_last;
        if (long$6) begin
            lines$6$last = line_last;
        end
        lines$6$write_enable = 1'b1;
        lines$6$data_in = two$6$q;
        head$7 = lines$6$data_out;
        lines$7$clock = clock;
        lines$7$last = ray_last;
        if (long$7) begin
            lines$7$last = line_last;
        end
        lines$7$write_enable = 1'b1;
        lines$7$data_in = two$7$q;
        head$8 = lines$7$data_out;
        one$0$clock = clock;
        two$0$clock = clock;
        one$0$d = head$0;
        two$0$d = one$0$q;
        one$1$clock = clock;
        two$1$clock = clock;
        one$1$d = head$1;
        two$1$d = one$1$q;
        one$2$clock = clock;
        two$2$clock = clock;
        one$2$d = head$2;
        two$2$d = one$2$q;
        one$3$clock = clock;
        two$3$clock = clock;
        one$3$d = head$3;
        two$3$d = one$3$q;
        one$4$clock = clock;
        two$4$clock = clock;
        one$4$d = head$4;
        two$4$d = one$4$q;
        one$5$clock = clock;
        two$5$clock = clock;
        one$5$d = head$5;
        two$5$d = one$5$q;
        one$6$clock = clock;
        two$6$clock = clock;
        one$6$d = head$6;
        two$6$d = one$6$q;
        one$7$clock = clock;
        two$7$clock = clock;
        one$7$d = head$7;
        two$7$d = one$7$q;
        one$8$clock = clock;
        two$8$clock = clock;
        one$8$d = head$8;
        two$8$d = one$8$q;
        t000 = head$0;
        t001 = one$0$q;
        t002 = two$0$q;
        t010 = head$1;
        t011 = one$1$q;
        t012 = two$1$q;
        t020 = head$2;
        t021 = one$2$q;
        t022 = two$2$q;
        t100 = head$3;
        t101 = one$3$q;
        t102 = two$3$q;
        t110 = head$4;
        t111 = one$4$q;
        t112 = two$4$q;
        t120 = head$5;
        t121 = one$5$q;
        t122 = two$5$q;
        t200 = head$6;
        t201 = one$6$q;
        t202 = two$6$q;
        t210 = head$7;
        t211 = one$7$q;
        t212 = two$7$q;
        t220 = head$8;
        t221 = one$8$q;
        t222 = two$8$q;
    end
    
endmodule // top$pipeline$abc$lanes$0
module top$pipeline$abc$lanes$0$lines$0(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$0$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$0$lines$0$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$0$lines$0$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$0
module top$pipeline$abc$lanes$0$lines$0$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$0$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$0$lines$0$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$0$lines$0$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$0$lines$0$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$0$line
module top$pipeline$abc$lanes$0$lines$0$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$0$line$one
module top$pipeline$abc$lanes$0$lines$0$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$0$line$ptr
module top$pipeline$abc$lanes$0$lines$0$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$0$lines$0$line$ram
module top$pipeline$abc$lanes$0$lines$0$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$0$line$rd_flipped
module top$pipeline$abc$lanes$0$lines$0$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$0$line_last
module top$pipeline$abc$lanes$0$lines$0$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$0$out
module top$pipeline$abc$lanes$0$lines$1(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$1$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$0$lines$1$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$0$lines$1$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$1
module top$pipeline$abc$lanes$0$lines$1$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$1$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$0$lines$1$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$0$lines$1$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$0$lines$1$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$1$line
module top$pipeline$abc$lanes$0$lines$1$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$1$line$one
module top$pipeline$abc$lanes$0$lines$1$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$1$line$ptr
module top$pipeline$abc$lanes$0$lines$1$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$0$lines$1$line$ram
module top$pipeline$abc$lanes$0$lines$1$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$1$line$rd_flipped
module top$pipeline$abc$lanes$0$lines$1$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$1$line_last
module top$pipeline$abc$lanes$0$lines$1$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$1$out
module top$pipeline$abc$lanes$0$lines$2(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$2$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$0$lines$2$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$0$lines$2$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$2
module top$pipeline$abc$lanes$0$lines$2$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h22b;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$2$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$0$lines$2$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$0$lines$2$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$0$lines$2$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$2$line
module top$pipeline$abc$lanes$0$lines$2$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$2$line$one
module top$pipeline$abc$lanes$0$lines$2$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$2$line$ptr
module top$pipeline$abc$lanes$0$lines$2$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[555:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[9:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$0$lines$2$line$ram
module top$pipeline$abc$lanes$0$lines$2$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$2$line$rd_flipped
module top$pipeline$abc$lanes$0$lines$2$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$2$line_last
module top$pipeline$abc$lanes$0$lines$2$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$2$out
module top$pipeline$abc$lanes$0$lines$3(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$3$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$0$lines$3$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$0$lines$3$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$3
module top$pipeline$abc$lanes$0$lines$3$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$3$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$0$lines$3$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$0$lines$3$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$0$lines$3$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$3$line
module top$pipeline$abc$lanes$0$lines$3$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$3$line$one
module top$pipeline$abc$lanes$0$lines$3$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$3$line$ptr
module top$pipeline$abc$lanes$0$lines$3$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$0$lines$3$line$ram
module top$pipeline$abc$lanes$0$lines$3$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$3$line$rd_flipped
module top$pipeline$abc$lanes$0$lines$3$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$3$line_last
module top$pipeline$abc$lanes$0$lines$3$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$3$out
module top$pipeline$abc$lanes$0$lines$4(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$4$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$0$lines$4$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$0$lines$4$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$4
module top$pipeline$abc$lanes$0$lines$4$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$4$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$0$lines$4$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$0$lines$4$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$0$lines$4$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$4$line
module top$pipeline$abc$lanes$0$lines$4$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$4$line$one
module top$pipeline$abc$lanes$0$lines$4$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$4$line$ptr
module top$pipeline$abc$lanes$0$lines$4$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$0$lines$4$line$ram
module top$pipeline$abc$lanes$0$lines$4$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$4$line$rd_flipped
module top$pipeline$abc$lanes$0$lines$4$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$4$line_last
module top$pipeline$abc$lanes$0$lines$4$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$4$out
module top$pipeline$abc$lanes$0$lines$5(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$5$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$0$lines$5$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$0$lines$5$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$5
module top$pipeline$abc$lanes$0$lines$5$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h22b;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$5$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$0$lines$5$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$0$lines$5$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$0$lines$5$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$5$line
module top$pipeline$abc$lanes$0$lines$5$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$5$line$one
module top$pipeline$abc$lanes$0$lines$5$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$5$line$ptr
module top$pipeline$abc$lanes$0$lines$5$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[555:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[9:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$0$lines$5$line$ram
module top$pipeline$abc$lanes$0$lines$5$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$5$line$rd_flipped
module top$pipeline$abc$lanes$0$lines$5$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$5$line_last
module top$pipeline$abc$lanes$0$lines$5$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$5$out
module top$pipeline$abc$lanes$0$lines$6(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$6$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$0$lines$6$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$0$lines$6$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$6
module top$pipeline$abc$lanes$0$lines$6$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$6$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$0$lines$6$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$0$lines$6$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$0$lines$6$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$6$line
module top$pipeline$abc$lanes$0$lines$6$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$6$line$one
module top$pipeline$abc$lanes$0$lines$6$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$6$line$ptr
module top$pipeline$abc$lanes$0$lines$6$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$0$lines$6$line$ram
module top$pipeline$abc$lanes$0$lines$6$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$6$line$rd_flipped
module top$pipeline$abc$lanes$0$lines$6$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$6$line_last
module top$pipeline$abc$lanes$0$lines$6$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$6$out
module top$pipeline$abc$lanes$0$lines$7(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$7$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$0$lines$7$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$0$lines$7$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$7
module top$pipeline$abc$lanes$0$lines$7$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$0$lines$7$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$0$lines$7$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$0$lines$7$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$0$lines$7$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$0$lines$7$line
module top$pipeline$abc$lanes$0$lines$7$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$7$line$one
module top$pipeline$abc$lanes$0$lines$7$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$7$line$ptr
module top$pipeline$abc$lanes$0$lines$7$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$0$lines$7$line$ram
module top$pipeline$abc$lanes$0$lines$7$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$7$line$rd_flipped
module top$pipeline$abc$lanes$0$lines$7$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$7$line_last
module top$pipeline$abc$lanes$0$lines$7$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$lines$7$out
module top$pipeline$abc$lanes$0$one$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$one$0
module top$pipeline$abc$lanes$0$one$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$one$1
module top$pipeline$abc$lanes$0$one$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$one$2
module top$pipeline$abc$lanes$0$one$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$one$3
module top$pipeline$abc$lanes$0$one$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$one$4
module top$pipeline$abc$lanes$0$one$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$one$5
module top$pipeline$abc$lanes$0$one$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$one$6
module top$pipeline$abc$lanes$0$one$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$one$7
module top$pipeline$abc$lanes$0$one$8(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$one$8
module top$pipeline$abc$lanes$0$two$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$two$0
module top$pipeline$abc$lanes$0$two$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$two$1
module top$pipeline$abc$lanes$0$two$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$two$2
module top$pipeline$abc$lanes$0$two$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$two$3
module top$pipeline$abc$lanes$0$two$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$two$4
module top$pipeline$abc$lanes$0$two$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$two$5
module top$pipeline$abc$lanes$0$two$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$two$6
module top$pipeline$abc$lanes$0$two$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$two$7
module top$pipeline$abc$lanes$0$two$8(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$0$two$8
module top$pipeline$abc$lanes$1(clock,ray_last,line_last,sample,t000,t001,t002,t010,t011,t012,t020,t021,t022,t100,t101,t102,t110,t111,t112,t120,t121,t122,t200,t201,t202,t210,t211,t212,t220,t221,t222);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] ray_last;
    input wire  [15:0] line_last;
    input wire  [31:0] sample;
    output reg  [31:0] t000;
    output reg  [31:0] t001;
    output reg  [31:0] t002;
    output reg  [31:0] t010;
    output reg  [31:0] t011;
    output reg  [31:0] t012;
    output reg  [31:0] t020;
    output reg  [31:0] t021;
    output reg  [31:0] t022;
    output reg  [31:0] t100;
    output reg  [31:0] t101;
    output reg  [31:0] t102;
    output reg  [31:0] t110;
    output reg  [31:0] t111;
    output reg  [31:0] t112;
    output reg  [31:0] t120;
    output reg  [31:0] t121;
    output reg  [31:0] t122;
    output reg  [31:0] t200;
    output reg  [31:0] t201;
    output reg  [31:0] t202;
    output reg  [31:0] t210;
    output reg  [31:0] t211;
    output reg  [31:0] t212;
    output reg  [31:0] t220;
    output reg  [31:0] t221;
    output reg  [31:0] t222;
    
    // Constant declarations
    localparam  long$0 = 1'b0;
    localparam  long$1 = 1'b0;
    localparam  long$2 = 1'b1;
    localparam  long$3 = 1'b0;
    localparam  long$4 = 1'b0;
    localparam  long$5 = 1'b1;
    localparam  long$6 = 1'b0;
    localparam  long$7 = 1'b0;
    
    // Stub signals
    reg  [31:0] one$0$d;
    wire  [31:0] one$0$q;
    reg  one$0$clock;
    reg  [31:0] one$1$d;
    wire  [31:0] one$1$q;
    reg  one$1$clock;
    reg  [31:0] one$2$d;
    wire  [31:0] one$2$q;
    reg  one$2$clock;
    reg  [31:0] one$3$d;
    wire  [31:0] one$3$q;
    reg  one$3$clock;
    reg  [31:0] one$4$d;
    wire  [31:0] one$4$q;
    reg  one$4$clock;
    reg  [31:0] one$5$d;
    wire  [31:0] one$5$q;
    reg  one$5$clock;
    reg  [31:0] one$6$d;
    wire  [31:0] one$6$q;
    reg  one$6$clock;
    reg  [31:0] one$7$d;
    wire  [31:0] one$7$q;
    reg  one$7$clock;
    reg  [31:0] one$8$d;
    wire  [31:0] one$8$q;
    reg  one$8$clock;
    reg  [31:0] two$0$d;
    wire  [31:0] two$0$q;
    reg  two$0$clock;
    reg  [31:0] two$1$d;
    wire  [31:0] two$1$q;
    reg  two$1$clock;
    reg  [31:0] two$2$d;
    wire  [31:0] two$2$q;
    reg  two$2$clock;
    reg  [31:0] two$3$d;
    wire  [31:0] two$3$q;
    reg  two$3$clock;
    reg  [31:0] two$4$d;
    wire  [31:0] two$4$q;
    reg  two$4$clock;
    reg  [31:0] two$5$d;
    wire  [31:0] two$5$q;
    reg  two$5$clock;
    reg  [31:0] two$6$d;
    wire  [31:0] two$6$q;
    reg  two$6$clock;
    reg  [31:0] two$7$d;
    wire  [31:0] two$7$q;
    reg  two$7$clock;
    reg  [31:0] two$8$d;
    wire  [31:0] two$8$q;
    reg  two$8$clock;
    reg  lines$0$clock;
    reg  [31:0] lines$0$data_in;
    reg  lines$0$write_enable;
    wire  [31:0] lines$0$data_out;
    reg  [15:0] lines$0$last;
    reg  lines$1$clock;
    reg  [31:0] lines$1$data_in;
    reg  lines$1$write_enable;
    wire  [31:0] lines$1$data_out;
    reg  [15:0] lines$1$last;
    reg  lines$2$clock;
    reg  [31:0] lines$2$data_in;
    reg  lines$2$write_enable;
    wire  [31:0] lines$2$data_out;
    reg  [15:0] lines$2$last;
    reg  lines$3$clock;
    reg  [31:0] lines$3$data_in;
    reg  lines$3$write_enable;
    wire  [31:0] lines$3$data_out;
    reg  [15:0] lines$3$last;
    reg  lines$4$clock;
    reg  [31:0] lines$4$data_in;
    reg  lines$4$write_enable;
    wire  [31:0] lines$4$data_out;
    reg  [15:0] lines$4$last;
    reg  lines$5$clock;
    reg  [31:0] lines$5$data_in;
    reg  lines$5$write_enable;
    wire  [31:0] lines$5$data_out;
    reg  [15:0] lines$5$last;
    reg  lines$6$clock;
    reg  [31:0] lines$6$data_in;
    reg  lines$6$write_enable;
    wire  [31:0] lines$6$data_out;
    reg  [15:0] lines$6$last;
    reg  lines$7$clock;
    reg  [31:0] lines$7$data_in;
    reg  lines$7$write_enable;
    wire  [31:0] lines$7$data_out;
    reg  [15:0] lines$7$last;
    
    // Local signals
    reg  [31:0] head$0;
    reg  [31:0] head$1;
    reg  [31:0] head$2;
    reg  [31:0] head$3;
    reg  [31:0] head$4;
    reg  [31:0] head$5;
    reg  [31:0] head$6;
    reg  [31:0] head$7;
    reg  [31:0] head$8;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$one$0 one$0(
        .d(one$0$d),
        .q(one$0$q),
        .clock(one$0$clock)
    );
    top$pipeline$abc$lanes$1$one$1 one$1(
        .d(one$1$d),
        .q(one$1$q),
        .clock(one$1$clock)
    );
    top$pipeline$abc$lanes$1$one$2 one$2(
        .d(one$2$d),
        .q(one$2$q),
        .clock(one$2$clock)
    );
    top$pipeline$abc$lanes$1$one$3 one$3(
        .d(one$3$d),
        .q(one$3$q),
        .clock(one$3$clock)
    );
    top$pipeline$abc$lanes$1$one$4 one$4(
        .d(one$4$d),
        .q(one$4$q),
        .clock(one$4$clock)
    );
    top$pipeline$abc$lanes$1$one$5 one$5(
        .d(one$5$d),
        .q(one$5$q),
        .clock(one$5$clock)
    );
    top$pipeline$abc$lanes$1$one$6 one$6(
        .d(one$6$d),
        .q(one$6$q),
        .clock(one$6$clock)
    );
    top$pipeline$abc$lanes$1$one$7 one$7(
        .d(one$7$d),
        .q(one$7$q),
        .clock(one$7$clock)
    );
    top$pipeline$abc$lanes$1$one$8 one$8(
        .d(one$8$d),
        .q(one$8$q),
        .clock(one$8$clock)
    );
    top$pipeline$abc$lanes$1$two$0 two$0(
        .d(two$0$d),
        .q(two$0$q),
        .clock(two$0$clock)
    );
    top$pipeline$abc$lanes$1$two$1 two$1(
        .d(two$1$d),
        .q(two$1$q),
        .clock(two$1$clock)
    );
    top$pipeline$abc$lanes$1$two$2 two$2(
        .d(two$2$d),
        .q(two$2$q),
        .clock(two$2$clock)
    );
    top$pipeline$abc$lanes$1$two$3 two$3(
        .d(two$3$d),
        .q(two$3$q),
        .clock(two$3$clock)
    );
    top$pipeline$abc$lanes$1$two$4 two$4(
        .d(two$4$d),
        .q(two$4$q),
        .clock(two$4$clock)
    );
    top$pipeline$abc$lanes$1$two$5 two$5(
        .d(two$5$d),
        .q(two$5$q),
        .clock(two$5$clock)
    );
    top$pipeline$abc$lanes$1$two$6 two$6(
        .d(two$6$d),
        .q(two$6$q),
        .clock(two$6$clock)
    );
    top$pipeline$abc$lanes$1$two$7 two$7(
        .d(two$7$d),
        .q(two$7$q),
        .clock(two$7$clock)
    );
    top$pipeline$abc$lanes$1$two$8 two$8(
        .d(two$8$d),
        .q(two$8$q),
        .clock(two$8$clock)
    );
    top$pipeline$abc$lanes$1$lines$0 lines$0(
        .clock(lines$0$clock),
        .data_in(lines$0$data_in),
        .write_enable(lines$0$write_enable),
        .data_out(lines$0$data_out),
        .last(lines$0$last)
    );
    top$pipeline$abc$lanes$1$lines$1 lines$1(
        .clock(lines$1$clock),
        .data_in(lines$1$data_in),
        .write_enable(lines$1$write_enable),
        .data_out(lines$1$data_out),
        .last(lines$1$last)
    );
    top$pipeline$abc$lanes$1$lines$2 lines$2(
        .clock(lines$2$clock),
        .data_in(lines$2$data_in),
        .write_enable(lines$2$write_enable),
        .data_out(lines$2$data_out),
        .last(lines$2$last)
    );
    top$pipeline$abc$lanes$1$lines$3 lines$3(
        .clock(lines$3$clock),
        .data_in(lines$3$data_in),
        .write_enable(lines$3$write_enable),
        .data_out(lines$3$data_out),
        .last(lines$3$last)
    );
    top$pipeline$abc$lanes$1$lines$4 lines$4(
        .clock(lines$4$clock),
        .data_in(lines$4$data_in),
        .write_enable(lines$4$write_enable),
        .data_out(lines$4$data_out),
        .last(lines$4$last)
    );
    top$pipeline$abc$lanes$1$lines$5 lines$5(
        .clock(lines$5$clock),
        .data_in(lines$5$data_in),
        .write_enable(lines$5$write_enable),
        .data_out(lines$5$data_out),
        .last(lines$5$last)
    );
    top$pipeline$abc$lanes$1$lines$6 lines$6(
        .clock(lines$6$clock),
        .data_in(lines$6$data_in),
        .write_enable(lines$6$write_enable),
        .data_out(lines$6$data_out),
        .last(lines$6$last)
    );
    top$pipeline$abc$lanes$1$lines$7 lines$7(
        .clock(lines$7$clock),
        .data_in(lines$7$data_in),
        .write_enable(lines$7$write_enable),
        .data_out(lines$7$data_out),
        .last(lines$7$last)
    );
    
    // Update code
    always @(*) begin
        head$0 = sample;
        lines$0$clock = clock;
        lines$0$last = ray_last;
        if (long$0) begin
            lines$0$last = line_last;
        end
        lines$0$write_enable = 1'b1;
        lines$0$data_in = two$0$q;
        head$1 = lines$0$data_out;
        lines$1$clock = clock;
        lines$1$last = ray_last;
        if (long$1) begin
            lines$1$last = line_last;
        end
        lines$1$write_enable = 1'b1;
        lines$1$data_in = two$1$q;
        head$2 = lines$1$data_out;
        lines$2$clock = clock;
        lines$2$last = ray_last;
        if (long$2) begin
            lines$2$last = line_last;
        end
        lines$2$write_enable = 1'b1;
        lines$2$data_in = two$2$q;
        head$3 = lines$2$data_out;
        lines$3$clock = clock;
        lines$3$last = ray_last;
        if (long$3) begin
            lines$3$last = line_last;
        end
        lines$3$write_enable = 1'b1;
        lines$3$data_in = two$3$q;
        head$4 = lines$3$data_out;
        lines$4$clock = clock;
        lines$4$last = ray_last;
        if (long$4) begin
            lines$4$last = line_last;
        end
        lines$4$write_enable = 1'b1;
        lines$4$data_in = two$4$q;
        head$5 = lines$4$data_out;
        lines$5$clock = clock;
        lines$5$last = ray_last;
        if (long$5) begin
            lines$5$last = line_last;
        end
        lines$5$write_enable = 1'b1;
        lines$5$data_in = two$5$q;
        head$6 = lines$5$data_out;
        lines$6$clock = clock;
        lines$6$last = ray_last;
        if (long$6) begin
            lines$6$last = line_last;
        end
        lines$6$write_enable = 1'b1;
        lines$6$data_in = two$6$q;
        head$7 = lines$6$data_out;
        lines$7$clock = clock;
        lines$7$last = ray_last;
        if (long$7) begin
            lines$7$last = line_last;
        end
        lines$7$write_enable = 1'b1;
        lines$7$data_in = two$7$q;
        head$8 = lines$7$data_out;
        one$0$clock = clock;
        two$0$clock = clock;
        one$0$d = head$0;
        two$0$d = one$0$q;
        one$1$clock = clock;
        two$1$clock = clock;
        one$1$d = head$1;
        two$1$d = one$1$q;
        one$2$clock = clock;
        two$2$clock = clock;
        one$2$d = head$2;
        two$2$d = one$2$q;
        one$3$clock = clock;
        two$3$clock = clock;
        one$3$d = head$3;
        two$3$d = one$3$q;
        one$4$clock = clock;
        two$4$clock = clock;
        one$4$d = head$4;
        two$4$d = one$4$q;
        one$5$clock = clock;
        two$5$clock = clock;
        one$5$d = head$5;
        two$5$d = one$5$q;
        one$6$clock = clock;
        two$6$clock = clock;
        one$6$d = head$6;
        two$6$d = one$6$q;
        one$7$clock = clock;
        two$7$clock = clock;
        one$7$d = head$7;
        two$7$d = one$7$q;
        one$8$clock = clock;
        two$8$clock = clock;
        one$8$d = head$8;
        two$8$d = one$8$q;
        t000 = head$0;
        t001 = one$0$q;
        t002 = two$0$q;
        t010 = head$1;
        t011 = one$1$q;
        t012 = two$1$q;
        t020 = head$2;
        t021 = one$2$q;
        t022 = two$2$q;
        t100 = head$3;
        t101 = one$3$q;
        t102 = two$3$q;
        t110 = head$4;
        t111 = one$4$q;
        t112 = two$4$q;
        t120 = head$5;
        t121 = one$5$q;
        t122 = two$5$q;
        t200 = head$6;
        t201 = one$6$q;
        t202 = two$6$q;
        t210 = head$7;
        t211 = one$7$q;
        t212 = two$7$q;
        t220 = head$8;
        t221 = one$8$q;
        t222 = two$8$q;
    end
    
endmodule // top$pipeline$abc$lanes$1
module top$pipeline$abc$lanes$1$lines$0(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$0$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$1$lines$0$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$1$lines$0$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$0
module top$pipeline$abc$lanes$1$lines$0$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$0$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$1$lines$0$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$1$lines$0$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$1$lines$0$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$0$line
module top$pipeline$abc$lanes$1$lines$0$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$0$line$one
module top$pipeline$abc$lanes$1$lines$0$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$0$line$ptr
module top$pipeline$abc$lanes$1$lines$0$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$1$lines$0$line$ram
module top$pipeline$abc$lanes$1$lines$0$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$0$line$rd_flipped
module top$pipeline$abc$lanes$1$lines$0$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$0$line_last
module top$pipeline$abc$lanes$1$lines$0$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$0$out
module top$pipeline$abc$lanes$1$lines$1(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$1$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$1$lines$1$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$1$lines$1$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$1
module top$pipeline$abc$lanes$1$lines$1$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$1$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$1$lines$1$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$1$lines$1$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$1$lines$1$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$1$line
module top$pipeline$abc$lanes$1$lines$1$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$1$line$one
module top$pipeline$abc$lanes$1$lines$1$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$1$line$ptr
module top$pipeline$abc$lanes$1$lines$1$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$1$lines$1$line$ram
module top$pipeline$abc$lanes$1$lines$1$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$1$line$rd_flipped
module top$pipeline$abc$lanes$1$lines$1$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$1$line_last
module top$pipeline$abc$lanes$1$lines$1$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$1$out
module top$pipeline$abc$lanes$1$lines$2(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$2$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$1$lines$2$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$1$lines$2$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$2
module top$pipeline$abc$lanes$1$lines$2$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h22b;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$2$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$1$lines$2$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$1$lines$2$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$1$lines$2$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$2$line
module top$pipeline$abc$lanes$1$lines$2$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$2$line$one
module top$pipeline$abc$lanes$1$lines$2$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$2$line$ptr
module top$pipeline$abc$lanes$1$lines$2$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[555:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[9:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$1$lines$2$line$ram
module top$pipeline$abc$lanes$1$lines$2$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$2$line$rd_flipped
module top$pipeline$abc$lanes$1$lines$2$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$2$line_last
module top$pipeline$abc$lanes$1$lines$2$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$2$out
module top$pipeline$abc$lanes$1$lines$3(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$3$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$1$lines$3$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$1$lines$3$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$3
module top$pipeline$abc$lanes$1$lines$3$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$3$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$1$lines$3$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$1$lines$3$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$1$lines$3$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$3$line
module top$pipeline$abc$lanes$1$lines$3$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$3$line$one
module top$pipeline$abc$lanes$1$lines$3$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$3$line$ptr
module top$pipeline$abc$lanes$1$lines$3$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$1$lines$3$line$ram
module top$pipeline$abc$lanes$1$lines$3$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$3$line$rd_flipped
module top$pipeline$abc$lanes$1$lines$3$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$3$line_last
module top$pipeline$abc$lanes$1$lines$3$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$3$out
module top$pipeline$abc$lanes$1$lines$4(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$4$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$1$lines$4$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$1$lines$4$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$4
module top$pipeline$abc$lanes$1$lines$4$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$4$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$1$lines$4$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$1$lines$4$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$1$lines$4$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$4$line
module top$pipeline$abc$lanes$1$lines$4$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$4$line$one
module top$pipeline$abc$lanes$1$lines$4$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$4$line$ptr
module top$pipeline$abc$lanes$1$lines$4$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$1$lines$4$line$ram
module top$pipeline$abc$lanes$1$lines$4$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$4$line$rd_flipped
module top$pipeline$abc$lanes$1$lines$4$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$4$line_last
module top$pipeline$abc$lanes$1$lines$4$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$4$out
module top$pipeline$abc$lanes$1$lines$5(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$5$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$1$lines$5$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$1$lines$5$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$5
module top$pipeline$abc$lanes$1$lines$5$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h22b;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$5$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$1$lines$5$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$1$lines$5$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$1$lines$5$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$5$line
module top$pipeline$abc$lanes$1$lines$5$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$5$line$one
module top$pipeline$abc$lanes$1$lines$5$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$5$line$ptr
module top$pipeline$abc$lanes$1$lines$5$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[555:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[9:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$1$lines$5$line$ram
module top$pipeline$abc$lanes$1$lines$5$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$5$line$rd_flipped
module top$pipeline$abc$lanes$1$lines$5$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$5$line_last
module top$pipeline$abc$lanes$1$lines$5$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$5$out
module top$pipeline$abc$lanes$1$lines$6(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$6$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$1$lines$6$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$1$lines$6$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$6
module top$pipeline$abc$lanes$1$lines$6$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$6$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$1$lines$6$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$1$lines$6$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$1$lines$6$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$6$line
module top$pipeline$abc$lanes$1$lines$6$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$6$line$one
module top$pipeline$abc$lanes$1$lines$6$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$6$line$ptr
module top$pipeline$abc$lanes$1$lines$6$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$1$lines$6$line$ram
module top$pipeline$abc$lanes$1$lines$6$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$6$line$rd_flipped
module top$pipeline$abc$lanes$1$lines$6$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$6$line_last
module top$pipeline$abc$lanes$1$lines$6$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$6$out
module top$pipeline$abc$lanes$1$lines$7(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$7$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$1$lines$7$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$1$lines$7$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$7
module top$pipeline$abc$lanes$1$lines$7$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$1$lines$7$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$1$lines$7$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$1$lines$7$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$1$lines$7$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$1$lines$7$line
module top$pipeline$abc$lanes$1$lines$7$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$7$line$one
module top$pipeline$abc$lanes$1$lines$7$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$7$line$ptr
module top$pipeline$abc$lanes$1$lines$7$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$1$lines$7$line$ram
module top$pipeline$abc$lanes$1$lines$7$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$7$line$rd_flipped
module top$pipeline$abc$lanes$1$lines$7$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$7$line_last
module top$pipeline$abc$lanes$1$lines$7$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$lines$7$out
module top$pipeline$abc$lanes$1$one$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$one$0
module top$pipeline$abc$lanes$1$one$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$one$1
module top$pipeline$abc$lanes$1$one$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$one$2
module top$pipeline$abc$lanes$1$one$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$one$3
module top$pipeline$abc$lanes$1$one$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$one$4
module top$pipeline$abc$lanes$1$one$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$one$5
module top$pipeline$abc$lanes$1$one$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$one$6
module top$pipeline$abc$lanes$1$one$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$one$7
module top$pipeline$abc$lanes$1$one$8(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$one$8
module top$pipeline$abc$lanes$1$two$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$two$0
module top$pipeline$abc$lanes$1$two$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$two$1
module top$pipeline$abc$lanes$1$two$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$two$2
module top$pipeline$abc$lanes$1$two$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$two$3
module top$pipeline$abc$lanes$1$two$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$two$4
module top$pipeline$abc$lanes$1$two$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$two$5
module top$pipeline$abc$lanes$1$two$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$two$6
module top$pipeline$abc$lanes$1$two$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$two$7
module top$pipeline$abc$lanes$1$two$8(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$1$two$8
module top$pipeline$abc$lanes$2(clock,ray_last,line_last,sample,t000,t001,t002,t010,t011,t012,t020,t021,t022,t100,t101,t102,t110,t111,t112,t120,t121,t122,t200,t201,t202,t210,t211,t212,t220,t221,t222);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] ray_last;
    input wire  [15:0] line_last;
    input wire  [31:0] sample;
    output reg  [31:0] t000;
    output reg  [31:0] t001;
    output reg  [31:0] t002;
    output reg  [31:0] t010;
    output reg  [31:0] t011;
    output reg  [31:0] t012;
    output reg  [31:0] t020;
    output reg  [31:0] t021;
    output reg  [31:0] t022;
    output reg  [31:0] t100;
    output reg  [31:0] t101;
    output reg  [31:0] t102;
    output reg  [31:0] t110;
    output reg  [31:0] t111;
    output reg  [31:0] t112;
    output reg  [31:0] t120;
    output reg  [31:0] t121;
    output reg  [31:0] t122;
    output reg  [31:0] t200;
    output reg  [31:0] t201;
    output reg  [31:0] t202;
    output reg  [31:0] t210;
    output reg  [31:0] t211;
    output reg  [31:0] t212;
    output reg  [31:0] t220;
    output reg  [31:0] t221;
    output reg  [31:0] t222;
    
    // Constant declarations
    localparam  long$0 = 1'b0;
    localparam  long$1 = 1'b0;
    localparam  long$2 = 1'b1;
    localparam  long$3 = 1'b0;
    localparam  long$4 = 1'b0;
    localparam  long$5 = 1'b1;
    localparam  long$6 = 1'b0;
    localparam  long$7 = 1'b0;
    
    // Stub signals
    reg  [31:0] one$0$d;
    wire  [31:0] one$0$q;
    reg  one$0$clock;
    reg  [31:0] one$1$d;
    wire  [31:0] one$1$q;
    reg  one$1$clock;
    reg  [31:0] one$2$d;
    wire  [31:0] one$2$q;
    reg  one$2$clock;
    reg  [31:0] one$3$d;
    wire  [31:0] one$3$q;
    reg  one$3$clock;
    reg  [31:0] one$4$d;
    wire  [31:0] one$4$q;
    reg  one$4$clock;
    reg  [31:0] one$5$d;
    wire  [31:0] one$5$q;
    reg  one$5$clock;
    reg  [31:0] one$6$d;
    wire  [31:0] one$6$q;
    reg  one$6$clock;
    reg  [31:0] one$7$d;
    wire  [31:0] one$7$q;
    reg  one$7$clock;
    reg  [31:0] one$8$d;
    wire  [31:0] one$8$q;
    reg  one$8$clock;
    reg  [31:0] two$0$d;
    wire  [31:0] two$0$q;
    reg  two$0$clock;
    reg  [31:0] two$1$d;
    wire  [31:0] two$1$q;
    reg  two$1$clock;
    reg  [31:0] two$2$d;
    wire  [31:0] two$2$q;
    reg  two$2$clock;
    reg  [31:0] two$3$d;
    wire  [31:0] two$3$q;
    reg  two$3$clock;
    reg  [31:0] two$4$d;
    wire  [31:0] two$4$q;
    reg  two$4$clock;
    reg  [31:0] two$5$d;
    wire  [31:0] two$5$q;
    reg  two$5$clock;
    reg  [31:0] two$6$d;
    wire  [31:0] two$6$q;
    reg  two$6$clock;
    reg  [31:0] two$7$d;
    wire  [31:0] two$7$q;
    reg  two$7$clock;
    reg  [31:0] two$8$d;
    wire  [31:0] two$8$q;
    reg  two$8$clock;
    reg  lines$0$clock;
    reg  [31:0] lines$0$data_in;
    reg  lines$0$write_enable;
    wire  [31:0] lines$0$data_out;
    reg  [15:0] lines$0$last;
    reg  lines$1$clock;
    reg  [31:0] lines$1$data_in;
    reg  lines$1$write_enable;
    wire  [31:0] lines$1$data_out;
    reg  [15:0] lines$1$last;
    reg  lines$2$clock;
    reg  [31:0] lines$2$data_in;
    reg  lines$2$write_enable;
    wire  [31:0] lines$2$data_out;
    reg  [15:0] lines$2$last;
    reg  lines$3$clock;
    reg  [31:0] lines$3$data_in;
    reg  lines$3$write_enable;
    wire  [31:0] lines$3$data_out;
    reg  [15:0] lines$3$last;
    reg  lines$4$clock;
    reg  [31:0] lines$4$data_in;
    reg  lines$4$write_enable;
    wire  [31:0] lines$4$data_out;
    reg  [15:0] lines$4$last;
    reg  lines$5$clock;
    reg  [31:0] lines$5$data_in;
    reg  lines$5$write_enable;
    wire  [31:0] lines$5$data_out;
    reg  [15:0] lines$5$last;
    reg  lines$6$clock;
    reg  [31:0] lines$6$data_in;
    reg  lines$6$write_enable;
    wire  [31:0] lines$6$data_out;
    reg  [15:0] lines$6$last;
    reg  lines$7$clock;
    reg  [31:0] lines$7$data_in;
    reg  lines$7$write_enable;
    wire  [31:0] lines$7$data_out;
    reg  [15:0] lines$7$last;
    
    // Local signals
    reg  [31:0] head$0;
    reg  [31:0] head$1;
    reg  [31:0] head$2;
    reg  [31:0] head$3;
    reg  [31:0] head$4;
    reg  [31:0] head$5;
    reg  [31:0] head$6;
    reg  [31:0] head$7;
    reg  [31:0] head$8;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$one$0 one$0(
        .d(one$0$d),
        .q(one$0$q),
        .clock(one$0$clock)
    );
    top$pipeline$abc$lanes$2$one$1 one$1(
        .d(one$1$d),
        .q(one$1$q),
        .clock(one$1$clock)
    );
    top$pipeline$abc$lanes$2$one$2 one$2(
        .d(one$2$d),
        .q(one$2$q),
        .clock(one$2$clock)
    );
    top$pipeline$abc$lanes$2$one$3 one$3(
        .d(one$3$d),
        .q(one$3$q),
        .clock(one$3$clock)
    );
    top$pipeline$abc$lanes$2$one$4 one$4(
        .d(one$4$d),
        .q(one$4$q),
        .clock(one$4$clock)
    );
    top$pipeline$abc$lanes$2$one$5 one$5(
        .d(one$5$d),
        .q(one$5$q),
        .clock(one$5$clock)
    );
    top$pipeline$abc$lanes$2$one$6 one$6(
        .d(one$6$d),
        .q(one$6$q),
        .clock(one$6$clock)
    );
    top$pipeline$abc$lanes$2$one$7 one$7(
        .d(one$7$d),
        .q(one$7$q),
        .clock(one$7$clock)
    );
    top$pipeline$abc$lanes$2$one$8 one$8(
        .d(one$8$d),
        .q(one$8$q),
        .clock(one$8$clock)
    );
    top$pipeline$abc$lanes$2$two$0 two$0(
        .d(two$0$d),
        .q(two$0$q),
        .clock(two$0$clock)
    );
    top$pipeline$abc$lanes$2$two$1 two$1(
        .d(two$1$d),
        .q(two$1$q),
        .clock(two$1$clock)
    );
    top$pipeline$abc$lanes$2$two$2 two$2(
        .d(two$2$d),
        .q(two$2$q),
        .clock(two$2$clock)
    );
    top$pipeline$abc$lanes$2$two$3 two$3(
        .d(two$3$d),
        .q(two$3$q),
        .clock(two$3$clock)
    );
    top$pipeline$abc$lanes$2$two$4 two$4(
        .d(two$4$d),
        .q(two$4$q),
        .clock(two$4$clock)
    );
    top$pipeline$abc$lanes$2$two$5 two$5(
        .d(two$5$d),
        .q(two$5$q),
        .clock(two$5$clock)
    );
    top$pipeline$abc$lanes$2$two$6 two$6(
        .d(two$6$d),
        .q(two$6$q),
        .clock(two$6$clock)
    );
    top$pipeline$abc$lanes$2$two$7 two$7(
        .d(two$7$d),
        .q(two$7$q),
        .clock(two$7$clock)
    );
    top$pipeline$abc$lanes$2$two$8 two$8(
        .d(two$8$d),
        .q(two$8$q),
        .clock(two$8$clock)
    );
    top$pipeline$abc$lanes$2$lines$0 lines$0(
        .clock(lines$0$clock),
        .data_in(lines$0$data_in),
        .write_enable(lines$0$write_enable),
        .data_out(lines$0$data_out),
        .last(lines$0$last)
    );
    top$pipeline$abc$lanes$2$lines$1 lines$1(
        .clock(lines$1$clock),
        .data_in(lines$1$data_in),
        .write_enable(lines$1$write_enable),
        .data_out(lines$1$data_out),
        .last(lines$1$last)
    );
    top$pipeline$abc$lanes$2$lines$2 lines$2(
        .clock(lines$2$clock),
        .data_in(lines$2$data_in),
        .write_enable(lines$2$write_enable),
        .data_out(lines$2$data_out),
        .last(lines$2$last)
    );
    top$pipeline$abc$lanes$2$lines$3 lines$3(
        .clock(lines$3$clock),
        .data_in(lines$3$data_in),
        .write_enable(lines$3$write_enable),
        .data_out(lines$3$data_out),
        .last(lines$3$last)
    );
    top$pipeline$abc$lanes$2$lines$4 lines$4(
        .clock(lines$4$clock),
        .data_in(lines$4$data_in),
        .write_enable(lines$4$write_enable),
        .data_out(lines$4$data_out),
        .last(lines$4$last)
    );
    top$pipeline$abc$lanes$2$lines$5 lines$5(
        .clock(lines$5$clock),
        .data_in(lines$5$data_in),
        .write_enable(lines$5$write_enable),
        .data_out(lines$5$data_out),
        .last(lines$5$last)
    );
    top$pipeline$abc$lanes$2$lines$6 lines$6(
        .clock(lines$6$clock),
        .data_in(lines$6$data_in),
        .write_enable(lines$6$write_enable),
        .data_out(lines$6$data_out),
        .last(lines$6$last)
    );
    top$pipeline$abc$lanes$2$lines$7 lines$7(
        .clock(lines$7$clock),
        .data_in(lines$7$data_in),
        .write_enable(lines$7$write_enable),
        .data_out(lines$7$data_out),
        .last(lines$7$last)
    );
    
    // Update code
    always @(*) begin
        head$0 = sample;
        lines$0$clock = clock;
        lines$0$last = ray_last;
        if (long$0) begin
            lines$0$last = line_last;
        end
        lines$0$write_enable = 1'b1;
        lines$0$data_in = two$0$q;
        head$1 = lines$0$data_out;
        lines$1$clock = clock;
        lines$1$last = ray_last;
        if (long$1) begin
            lines$1$last = line_last;
        end
        lines$1$write_enable = 1'b1;
        lines$1$data_in = two$1$q;
        head$2 = lines$1$data_out;
        lines$2$clock = clock;
        lines$2$last = ray_last;
        if (long$2) begin
            lines$2$last = line_last;
        end
        lines$2$write_enable = 1'b1;
        lines$2$data_in = two$2$q;
        head$3 = lines$2$data_out;
        lines$3$clock = clock;
        lines$3$last = ray_last;
        if (long$3) begin
            lines$3$last = line_last;
        end
        lines$3$write_enable = 1'b1;
        lines$3$data_in = two$3$q;
        head$4 = lines$3$data_out;
        lines$4$clock = clock;
        lines$4$last = ray_last;
        if (long$4) begin
            lines$4$last = line_last;
        end
        lines$4$write_enable = 1'b1;
        lines$4$data_in = two$4$q;
        head$5 = lines$4$data_out;
        lines$5$clock = clock;
        lines$5$last = ray_last;
        if (long$5) begin
            lines$5$last = line_last;
        end
        lines$5$write_enable = 1'b1;
        lines$5$data_in = two$5$q;
        head$6 = lines$5$data_out;
        lines$6$clock = clock;
        lines$6$last = ray_last;
        if (long$6) begin
            lines$6$last = line_last;
        end
        lines$6$write_enable = 1'b1;
        lines$6$data_in = two$6$q;
        head$7 = lines$6$data_out;
        lines$7$clock = clock;
        lines$7$last = ray_last;
        if (long$7) begin
            lines$7$last = line_last;
        end
        lines$7$write_enable = 1'b1;
        lines$7$data_in = two$7$q;
        head$8 = lines$7$data_out;
        one$0$clock = clock;
        two$0$clock = clock;
        one$0$d = head$0;
        two$0$d = one$0$q;
        one$1$clock = clock;
        two$1$clock = clock;
        one$1$d = head$1;
        two$1$d = one$1$q;
        one$2$clock = clock;
        two$2$clock = clock;
        one$2$d = head$2;
        two$2$d = one$2$q;
        one$3$clock = clock;
        two$3$clock = clock;
        one$3$d = head$3;
        two$3$d = one$3$q;
        one$4$clock = clock;
        two$4$clock = clock;
        one$4$d = head$4;
        two$4$d = one$4$q;
        one$5$clock = clock;
        two$5$clock = clock;
        one$5$d = head$5;
        two$5$d = one$5$q;
        one$6$clock = clock;
        two$6$clock = clock;
        one$6$d = head$6;
        two$6$d = one$6$q;
        one$7$clock = clock;
        two$7$clock = clock;
        one$7$d = head$7;
        two$7$d = one$7$q;
        one$8$clock = clock;
        two$8$clock = clock;
        one$8$d = head$8;
        two$8$d = one$8$q;
        t000 = head$0;
        t001 = one$0$q;
        t002 = two$0$q;
        t010 = head$1;
        t011 = one$1$q;
        t012 = two$1$q;
        t020 = head$2;
        t021 = one$2$q;
        t022 = two$2$q;
        t100 = head$3;
        t101 = one$3$q;
        t102 = two$3$q;
        t110 = head$4;
        t111 = one$4$q;
        t112 = two$4$q;
        t120 = head$5;
        t121 = one$5$q;
        t122 = two$5$q;
        t200 = head$6;
        t201 = one$6$q;
        t202 = two$6$q;
        t210 = head$7;
        t211 = one$7$q;
        t212 = two$7$q;
        t220 = head$8;
        t221 = one$8$q;
        t222 = two$8$q;
    end
    
endmodule // top$pipeline$abc$lanes$2
module top$pipeline$abc$lanes$2$lines$0(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$0$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$2$lines$0$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$2$lines$0$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$0
module top$pipeline$abc$lanes$2$lines$0$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$0$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$2$lines$0$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$2$lines$0$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$2$lines$0$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$0$line
module top$pipeline$abc$lanes$2$lines$0$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$0$line$one
module top$pipeline$abc$lanes$2$lines$0$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$0$line$ptr
module top$pipeline$abc$lanes$2$lines$0$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$2$lines$0$line$ram
module top$pipeline$abc$lanes$2$lines$0$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$0$line$rd_flipped
module top$pipeline$abc$lanes$2$lines$0$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$0$line_last
module top$pipeline$abc$lanes$2$lines$0$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$0$out
module top$pipeline$abc$lanes$2$lines$1(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$1$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$2$lines$1$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$2$lines$1$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$1
module top$pipeline$abc$lanes$2$lines$1$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$1$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$2$lines$1$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$2$lines$1$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$2$lines$1$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$1$line
module top$pipeline$abc$lanes$2$lines$1$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$1$line$one
module top$pipeline$abc$lanes$2$lines$1$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$1$line$ptr
module top$pipeline$abc$lanes$2$lines$1$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$2$lines$1$line$ram
module top$pipeline$abc$lanes$2$lines$1$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$1$line$rd_flipped
module top$pipeline$abc$lanes$2$lines$1$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$1$line_last
module top$pipeline$abc$lanes$2$lines$1$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$1$out
module top$pipeline$abc$lanes$2$lines$2(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$2$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$2$lines$2$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$2$lines$2$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$2
module top$pipeline$abc$lanes$2$lines$2$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h22b;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$2$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$2$lines$2$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$2$lines$2$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$2$lines$2$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$2$line
module top$pipeline$abc$lanes$2$lines$2$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$2$line$one
module top$pipeline$abc$lanes$2$lines$2$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$2$line$ptr
module top$pipeline$abc$lanes$2$lines$2$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[555:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[9:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$2$lines$2$line$ram
module top$pipeline$abc$lanes$2$lines$2$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$2$line$rd_flipped
module top$pipeline$abc$lanes$2$lines$2$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$2$line_last
module top$pipeline$abc$lanes$2$lines$2$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$2$out
module top$pipeline$abc$lanes$2$lines$3(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$3$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$2$lines$3$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$2$lines$3$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$3
module top$pipeline$abc$lanes$2$lines$3$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$3$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$2$lines$3$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$2$lines$3$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$2$lines$3$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$3$line
module top$pipeline$abc$lanes$2$lines$3$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$3$line$one
module top$pipeline$abc$lanes$2$lines$3$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$3$line$ptr
module top$pipeline$abc$lanes$2$lines$3$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$2$lines$3$line$ram
module top$pipeline$abc$lanes$2$lines$3$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$3$line$rd_flipped
module top$pipeline$abc$lanes$2$lines$3$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$3$line_last
module top$pipeline$abc$lanes$2$lines$3$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$3$out
module top$pipeline$abc$lanes$2$lines$4(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$4$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$2$lines$4$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$2$lines$4$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$4
module top$pipeline$abc$lanes$2$lines$4$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$4$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$2$lines$4$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$2$lines$4$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$2$lines$4$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$4$line
module top$pipeline$abc$lanes$2$lines$4$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$4$line$one
module top$pipeline$abc$lanes$2$lines$4$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$4$line$ptr
module top$pipeline$abc$lanes$2$lines$4$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$2$lines$4$line$ram
module top$pipeline$abc$lanes$2$lines$4$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$4$line$rd_flipped
module top$pipeline$abc$lanes$2$lines$4$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$4$line_last
module top$pipeline$abc$lanes$2$lines$4$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$4$out
module top$pipeline$abc$lanes$2$lines$5(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$5$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$2$lines$5$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$2$lines$5$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$5
module top$pipeline$abc$lanes$2$lines$5$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h22b;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$5$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$2$lines$5$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$2$lines$5$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$2$lines$5$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$5$line
module top$pipeline$abc$lanes$2$lines$5$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$5$line$one
module top$pipeline$abc$lanes$2$lines$5$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$5$line$ptr
module top$pipeline$abc$lanes$2$lines$5$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[555:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[9:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$2$lines$5$line$ram
module top$pipeline$abc$lanes$2$lines$5$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$5$line$rd_flipped
module top$pipeline$abc$lanes$2$lines$5$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$5$line_last
module top$pipeline$abc$lanes$2$lines$5$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$5$out
module top$pipeline$abc$lanes$2$lines$6(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$6$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$2$lines$6$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$2$lines$6$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$6
module top$pipeline$abc$lanes$2$lines$6$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$6$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$2$lines$6$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$2$lines$6$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$2$lines$6$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$6$line
module top$pipeline$abc$lanes$2$lines$6$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$6$line$one
module top$pipeline$abc$lanes$2$lines$6$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$6$line$ptr
module top$pipeline$abc$lanes$2$lines$6$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$2$lines$6$line$ram
module top$pipeline$abc$lanes$2$lines$6$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$6$line$rd_flipped
module top$pipeline$abc$lanes$2$lines$6$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$6$line_last
module top$pipeline$abc$lanes$2$lines$6$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$6$out
module top$pipeline$abc$lanes$2$lines$7(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$7$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$2$lines$7$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$2$lines$7$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$7
module top$pipeline$abc$lanes$2$lines$7$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$2$lines$7$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$2$lines$7$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$2$lines$7$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$2$lines$7$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$2$lines$7$line
module top$pipeline$abc$lanes$2$lines$7$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$7$line$one
module top$pipeline$abc$lanes$2$lines$7$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$7$line$ptr
module top$pipeline$abc$lanes$2$lines$7$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$2$lines$7$line$ram
module top$pipeline$abc$lanes$2$lines$7$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$7$line$rd_flipped
module top$pipeline$abc$lanes$2$lines$7$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$7$line_last
module top$pipeline$abc$lanes$2$lines$7$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$lines$7$out
module top$pipeline$abc$lanes$2$one$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$one$0
module top$pipeline$abc$lanes$2$one$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$one$1
module top$pipeline$abc$lanes$2$one$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$one$2
module top$pipeline$abc$lanes$2$one$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$one$3
module top$pipeline$abc$lanes$2$one$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$one$4
module top$pipeline$abc$lanes$2$one$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$one$5
module top$pipeline$abc$lanes$2$one$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$one$6
module top$pipeline$abc$lanes$2$one$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$one$7
module top$pipeline$abc$lanes$2$one$8(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$one$8
module top$pipeline$abc$lanes$2$two$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$two$0
module top$pipeline$abc$lanes$2$two$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$two$1
module top$pipeline$abc$lanes$2$two$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$two$2
module top$pipeline$abc$lanes$2$two$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$two$3
module top$pipeline$abc$lanes$2$two$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$two$4
module top$pipeline$abc$lanes$2$two$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$two$5
module top$pipeline$abc$lanes$2$two$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$two$6
module top$pipeline$abc$lanes$2$two$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$two$7
module top$pipeline$abc$lanes$2$two$8(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$2$two$8
module top$pipeline$abc$lanes$3(clock,ray_last,line_last,sample,t000,t001,t002,t010,t011,t012,t020,t021,t022,t100,t101,t102,t110,t111,t112,t120,t121,t122,t200,t201,t202,t210,t211,t212,t220,t221,t222);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] ray_last;
    input wire  [15:0] line_last;
    input wire  [31:0] sample;
    output reg  [31:0] t000;
    output reg  [31:0] t001;
    output reg  [31:0] t002;
    output reg  [31:0] t010;
    output reg  [31:0] t011;
    output reg  [31:0] t012;
    output reg  [31:0] t020;
    output reg  [31:0] t021;
    output reg  [31:0] t022;
    output reg  [31:0] t100;
    output reg  [31:0] t101;
    output reg  [31:0] t102;
    output reg  [31:0] t110;
    output reg  [31:0] t111;
    output reg  [31:0] t112;
    output reg  [31:0] t120;
    output reg  [31:0] t121;
    output reg  [31:0] t122;
    output reg  [31:0] t200;
    output reg  [31:0] t201;
    output reg  [31:0] t202;
    output reg  [31:0] t210;
    output reg  [31:0] t211;
    output reg  [31:0] t212;
    output reg  [31:0] t220;
    output reg  [31:0] t221;
    output reg  [31:0] t222;
    
    // Constant declarations
    localparam  long$0 = 1'b0;
    localparam  long$1 = 1'b0;
    localparam  long$2 = 1'b1;
    localparam  long$3 = 1'b0;
    localparam  long$4 = 1'b0;
    localparam  long$5 = 1'b1;
    localparam  long$6 = 1'b0;
    localparam  long$7 = 1'b0;
    
    // Stub signals
    reg  [31:0] one$0$d;
    wire  [31:0] one$0$q;
    reg  one$0$clock;
    reg  [31:0] one$1$d;
    wire  [31:0] one$1$q;
    reg  one$1$clock;
    reg  [31:0] one$2$d;
    wire  [31:0] one$2$q;
    reg  one$2$clock;
    reg  [31:0] one$3$d;
    wire  [31:0] one$3$q;
    reg  one$3$clock;
    reg  [31:0] one$4$d;
    wire  [31:0] one$4$q;
    reg  one$4$clock;
    reg  [31:0] one$5$d;
    wire  [31:0] one$5$q;
    reg  one$5$clock;
    reg  [31:0] one$6$d;
    wire  [31:0] one$6$q;
    reg  one$6$clock;
    reg  [31:0] one$7$d;
    wire  [31:0] one$7$q;
    reg  one$7$clock;
    reg  [31:0] one$8$d;
    wire  [31:0] one$8$q;
    reg  one$8$clock;
    reg  [31:0] two$0$d;
    wire  [31:0] two$0$q;
    reg  two$0$clock;
    reg  [31:0] two$1$d;
    wire  [31:0] two$1$q;
    reg  two$1$clock;
    reg  [31:0] two$2$d;
    wire  [31:0] two$2$q;
    reg  two$2$clock;
    reg  [31:0] two$3$d;
    wire  [31:0] two$3$q;
    reg  two$3$clock;
    reg  [31:0] two$4$d;
    wire  [31:0] two$4$q;
    reg  two$4$clock;
    reg  [31:0] two$5$d;
    wire  [31:0] two$5$q;
    reg  two$5$clock;
    reg  [31:0] two$6$d;
    wire  [31:0] two$6$q;
    reg  two$6$clock;
    reg  [31:0] two$7$d;
    wire  [31:0] two$7$q;
    reg  two$7$clock;
    reg  [31:0] two$8$d;
    wire  [31:0] two$8$q;
    reg  two$8$clock;
    reg  lines$0$clock;
    reg  [31:0] lines$0$data_in;
    reg  lines$0$write_enable;
    wire  [31:0] lines$0$data_out;
    reg  [15:0] lines$0$last;
    reg  lines$1$clock;
    reg  [31:0] lines$1$data_in;
    reg  lines$1$write_enable;
    wire  [31:0] lines$1$data_out;
    reg  [15:0] lines$1$last;
    reg  lines$2$clock;
    reg  [31:0] lines$2$data_in;
    reg  lines$2$write_enable;
    wire  [31:0] lines$2$data_out;
    reg  [15:0] lines$2$last;
    reg  lines$3$clock;
    reg  [31:0] lines$3$data_in;
    reg  lines$3$write_enable;
    wire  [31:0] lines$3$data_out;
    reg  [15:0] lines$3$last;
    reg  lines$4$clock;
    reg  [31:0] lines$4$data_in;
    reg  lines$4$write_enable;
    wire  [31:0] lines$4$data_out;
    reg  [15:0] lines$4$last;
    reg  lines$5$clock;
    reg  [31:0] lines$5$data_in;
    reg  lines$5$write_enable;
    wire  [31:0] lines$5$data_out;
    reg  [15:0] lines$5$last;
    reg  lines$6$clock;
    reg  [31:0] lines$6$data_in;
    reg  lines$6$write_enable;
    wire  [31:0] lines$6$data_out;
    reg  [15:0] lines$6$last;
    reg  lines$7$clock;
    reg  [31:0] lines$7$data_in;
    reg  lines$7$write_enable;
    wire  [31:0] lines$7$data_out;
    reg  [15:0] lines$7$last;
    
    // Local signals
    reg  [31:0] head$0;
    reg  [31:0] head$1;
    reg  [31:0] head$2;
    reg  [31:0] head$3;
    reg  [31:0] head$4;
    reg  [31:0] head$5;
    reg  [31:0] head$6;
    reg  [31:0] head$7;
    reg  [31:0] head$8;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$one$0 one$0(
        .d(one$0$d),
        .q(one$0$q),
        .clock(one$0$clock)
    );
    top$pipeline$abc$lanes$3$one$1 one$1(
        .d(one$1$d),
        .q(one$1$q),
        .clock(one$1$clock)
    );
    top$pipeline$abc$lanes$3$one$2 one$2(
        .d(one$2$d),
        .q(one$2$q),
        .clock(one$2$clock)
    );
    top$pipeline$abc$lanes$3$one$3 one$3(
        .d(one$3$d),
        .q(one$3$q),
        .clock(one$3$clock)
    );
    top$pipeline$abc$lanes$3$one$4 one$4(
        .d(one$4$d),
        .q(one$4$q),
        .clock(one$4$clock)
    );
    top$pipeline$abc$lanes$3$one$5 one$5(
        .d(one$5$d),
        .q(one$5$q),
        .clock(one$5$clock)
    );
    top$pipeline$abc$lanes$3$one$6 one$6(
        .d(one$6$d),
        .q(one$6$q),
        .clock(one$6$clock)
    );
    top$pipeline$abc$lanes$3$one$7 one$7(
        .d(one$7$d),
        .q(one$7$q),
        .clock(one$7$clock)
    );
    top$pipeline$abc$lanes$3$one$8 one$8(
        .d(one$8$d),
        .q(one$8$q),
        .clock(one$8$clock)
    );
    top$pipeline$abc$lanes$3$two$0 two$0(
        .d(two$0$d),
        .q(two$0$q),
        .clock(two$0$clock)
    );
    top$pipeline$abc$lanes$3$two$1 two$1(
        .d(two$1$d),
        .q(two$1$q),
        .clock(two$1$clock)
    );
    top$pipeline$abc$lanes$3$two$2 two$2(
        .d(two$2$d),
        .q(two$2$q),
        .clock(two$2$clock)
    );
    top$pipeline$abc$lanes$3$two$3 two$3(
        .d(two$3$d),
        .q(two$3$q),
        .clock(two$3$clock)
    );
    top$pipeline$abc$lanes$3$two$4 two$4(
        .d(two$4$d),
        .q(two$4$q),
        .clock(two$4$clock)
    );
    top$pipeline$abc$lanes$3$two$5 two$5(
        .d(two$5$d),
        .q(two$5$q),
        .clock(two$5$clock)
    );
    top$pipeline$abc$lanes$3$two$6 two$6(
        .d(two$6$d),
        .q(two$6$q),
        .clock(two$6$clock)
    );
    top$pipeline$abc$lanes$3$two$7 two$7(
        .d(two$7$d),
        .q(two$7$q),
        .clock(two$7$clock)
    );
    top$pipeline$abc$lanes$3$two$8 two$8(
        .d(two$8$d),
        .q(two$8$q),
        .clock(two$8$clock)
    );
    top$pipeline$abc$lanes$3$lines$0 lines$0(
        .clock(lines$0$clock),
        .data_in(lines$0$data_in),
        .write_enable(lines$0$write_enable),
        .data_out(lines$0$data_out),
        .last(lines$0$last)
    );
    top$pipeline$abc$lanes$3$lines$1 lines$1(
        .clock(lines$1$clock),
        .data_in(lines$1$data_in),
        .write_enable(lines$1$write_enable),
        .data_out(lines$1$data_out),
        .last(lines$1$last)
    );
    top$pipeline$abc$lanes$3$lines$2 lines$2(
        .clock(lines$2$clock),
        .data_in(lines$2$data_in),
        .write_enable(lines$2$write_enable),
        .data_out(lines$2$data_out),
        .last(lines$2$last)
    );
    top$pipeline$abc$lanes$3$lines$3 lines$3(
        .clock(lines$3$clock),
        .data_in(lines$3$data_in),
        .write_enable(lines$3$write_enable),
        .data_out(lines$3$data_out),
        .last(lines$3$last)
    );
    top$pipeline$abc$lanes$3$lines$4 lines$4(
        .clock(lines$4$clock),
        .data_in(lines$4$data_in),
        .write_enable(lines$4$write_enable),
        .data_out(lines$4$data_out),
        .last(lines$4$last)
    );
    top$pipeline$abc$lanes$3$lines$5 lines$5(
        .clock(lines$5$clock),
        .data_in(lines$5$data_in),
        .write_enable(lines$5$write_enable),
        .data_out(lines$5$data_out),
        .last(lines$5$last)
    );
    top$pipeline$abc$lanes$3$lines$6 lines$6(
        .clock(lines$6$clock),
        .data_in(lines$6$data_in),
        .write_enable(lines$6$write_enable),
        .data_out(lines$6$data_out),
        .last(lines$6$last)
    );
    top$pipeline$abc$lanes$3$lines$7 lines$7(
        .clock(lines$7$clock),
        .data_in(lines$7$data_in),
        .write_enable(lines$7$write_enable),
        .data_out(lines$7$data_out),
        .last(lines$7$last)
    );
    
    // Update code
    always @(*) begin
        head$0 = sample;
        lines$0$clock = clock;
        lines$0$last = ray_last;
        if (long$0) begin
            lines$0$last = line_last;
        end
        lines$0$write_enable = 1'b1;
        lines$0$data_in = two$0$q;
        head$1 = lines$0$data_out;
        lines$1$clock = clock;
        lines$1$last = ray_last;
        if (long$1) begin
            lines$1$last = line_last;
        end
        lines$1$write_enable = 1'b1;
        lines$1$data_in = two$1$q;
        head$2 = lines$1$data_out;
        lines$2$clock = clock;
        lines$2$last = ray_last;
        if (long$2) begin
            lines$2$last = line_last;
        end
        lines$2$write_enable = 1'b1;
        lines$2$data_in = two$2$q;
        head$3 = lines$2$data_out;
        lines$3$clock = clock;
        lines$3$last = ray_last;
        if (long$3) begin
            lines$3$last = line_last;
        end
        lines$3$write_enable = 1'b1;
        lines$3$data_in = two$3$q;
        head$4 = lines$3$data_out;
        lines$4$clock = clock;
        lines$4$last = ray_last;
        if (long$4) begin
            lines$4$last = line_last;
        end
        lines$4$write_enable = 1'b1;
        lines$4$data_in = two$4$q;
        head$5 = lines$4$data_out;
        lines$5$clock = clock;
        lines$5$last = ray_last;
        if (long$5) begin
            lines$5$last = line_last;
        end
        lines$5$write_enable = 1'b1;
        lines$5$data_in = two$5$q;
        head$6 = lines$5$data_out;
        lines$6$clock = clock;
        lines$6$last = ray_last;
        if (long$6) begin
            lines$6$last = line_last;
        end
        lines$6$write_enable = 1'b1;
        lines$6$data_in = two$6$q;
        head$7 = lines$6$data_out;
        lines$7$clock = clock;
        lines$7$last = ray_last;
        if (long$7) begin
            lines$7$last = line_last;
        end
        lines$7$write_enable = 1'b1;
        lines$7$data_in = two$7$q;
        head$8 = lines$7$data_out;
        one$0$clock = clock;
        two$0$clock = clock;
        one$0$d = head$0;
        two$0$d = one$0$q;
        one$1$clock = clock;
        two$1$clock = clock;
        one$1$d = head$1;
        two$1$d = one$1$q;
        one$2$clock = clock;
        two$2$clock = clock;
        one$2$d = head$2;
        two$2$d = one$2$q;
        one$3$clock = clock;
        two$3$clock = clock;
        one$3$d = head$3;
        two$3$d = one$3$q;
        one$4$clock = clock;
        two$4$clock = clock;
        one$4$d = head$4;
        two$4$d = one$4$q;
        one$5$clock = clock;
        two$5$clock = clock;
        one$5$d = head$5;
        two$5$d = one$5$q;
        one$6$clock = clock;
        two$6$clock = clock;
        one$6$d = head$6;
        two$6$d = one$6$q;
        one$7$clock = clock;
        two$7$clock = clock;
        one$7$d = head$7;
        two$7$d = one$7$q;
        one$8$clock = clock;
        two$8$clock = clock;
        one$8$d = head$8;
        two$8$d = one$8$q;
        t000 = head$0;
        t001 = one$0$q;
        t002 = two$0$q;
        t010 = head$1;
        t011 = one$1$q;
        t012 = two$1$q;
        t020 = head$2;
        t021 = one$2$q;
        t022 = two$2$q;
        t100 = head$3;
        t101 = one$3$q;
        t102 = two$3$q;
        t110 = head$4;
        t111 = one$4$q;
        t112 = two$4$q;
        t120 = head$5;
        t121 = one$5$q;
        t122 = two$5$q;
        t200 = head$6;
        t201 = one$6$q;
        t202 = two$6$q;
        t210 = head$7;
        t211 = one$7$q;
        t212 = two$7$q;
        t220 = head$8;
        t221 = one$8$q;
        t222 = two$8$q;
    end
    
endmodule // top$pipeline$abc$lanes$3
module top$pipeline$abc$lanes$3$lines$0(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$0$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$3$lines$0$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$3$lines$0$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$0
module top$pipeline$abc$lanes$3$lines$0$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$0$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$3$lines$0$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$3$lines$0$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$3$lines$0$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$0$line
module top$pipeline$abc$lanes$3$lines$0$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$0$line$one
module top$pipeline$abc$lanes$3$lines$0$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$0$line$ptr
module top$pipeline$abc$lanes$3$lines$0$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$3$lines$0$line$ram
module top$pipeline$abc$lanes$3$lines$0$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$0$line$rd_flipped
module top$pipeline$abc$lanes$3$lines$0$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$0$line_last
module top$pipeline$abc$lanes$3$lines$0$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$0$out
module top$pipeline$abc$lanes$3$lines$1(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$1$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$3$lines$1$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$3$lines$1$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$1
module top$pipeline$abc$lanes$3$lines$1$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$1$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$3$lines$1$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$3$lines$1$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$3$lines$1$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$1$line
module top$pipeline$abc$lanes$3$lines$1$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$1$line$one
module top$pipeline$abc$lanes$3$lines$1$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$1$line$ptr
module top$pipeline$abc$lanes$3$lines$1$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$3$lines$1$line$ram
module top$pipeline$abc$lanes$3$lines$1$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$1$line$rd_flipped
module top$pipeline$abc$lanes$3$lines$1$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$1$line_last
module top$pipeline$abc$lanes$3$lines$1$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$1$out
module top$pipeline$abc$lanes$3$lines$2(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$2$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$3$lines$2$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$3$lines$2$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$2
module top$pipeline$abc$lanes$3$lines$2$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h22b;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$2$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$3$lines$2$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$3$lines$2$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$3$lines$2$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$2$line
module top$pipeline$abc$lanes$3$lines$2$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$2$line$one
module top$pipeline$abc$lanes$3$lines$2$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$2$line$ptr
module top$pipeline$abc$lanes$3$lines$2$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[555:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[9:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$3$lines$2$line$ram
module top$pipeline$abc$lanes$3$lines$2$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$2$line$rd_flipped
module top$pipeline$abc$lanes$3$lines$2$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$2$line_last
module top$pipeline$abc$lanes$3$lines$2$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$2$out
module top$pipeline$abc$lanes$3$lines$3(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$3$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$3$lines$3$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$3$lines$3$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$3
module top$pipeline$abc$lanes$3$lines$3$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$3$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$3$lines$3$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$3$lines$3$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$3$lines$3$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$3$line
module top$pipeline$abc$lanes$3$lines$3$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$3$line$one
module top$pipeline$abc$lanes$3$lines$3$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$3$line$ptr
module top$pipeline$abc$lanes$3$lines$3$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$3$lines$3$line$ram
module top$pipeline$abc$lanes$3$lines$3$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$3$line$rd_flipped
module top$pipeline$abc$lanes$3$lines$3$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$3$line_last
module top$pipeline$abc$lanes$3$lines$3$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$3$out
module top$pipeline$abc$lanes$3$lines$4(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$4$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$3$lines$4$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$3$lines$4$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$4
module top$pipeline$abc$lanes$3$lines$4$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$4$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$3$lines$4$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$3$lines$4$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$3$lines$4$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$4$line
module top$pipeline$abc$lanes$3$lines$4$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$4$line$one
module top$pipeline$abc$lanes$3$lines$4$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$4$line$ptr
module top$pipeline$abc$lanes$3$lines$4$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$3$lines$4$line$ram
module top$pipeline$abc$lanes$3$lines$4$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$4$line$rd_flipped
module top$pipeline$abc$lanes$3$lines$4$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$4$line_last
module top$pipeline$abc$lanes$3$lines$4$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$4$out
module top$pipeline$abc$lanes$3$lines$5(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$5$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$3$lines$5$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$3$lines$5$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$5
module top$pipeline$abc$lanes$3$lines$5$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h22b;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$5$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$3$lines$5$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$3$lines$5$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$3$lines$5$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$5$line
module top$pipeline$abc$lanes$3$lines$5$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$5$line$one
module top$pipeline$abc$lanes$3$lines$5$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$5$line$ptr
module top$pipeline$abc$lanes$3$lines$5$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg [31:0] mem[555:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[9:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[9:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$3$lines$5$line$ram
module top$pipeline$abc$lanes$3$lines$5$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$5$line$rd_flipped
module top$pipeline$abc$lanes$3$lines$5$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$5$line_last
module top$pipeline$abc$lanes$3$lines$5$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$5$out
module top$pipeline$abc$lanes$3$lines$6(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$6$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$3$lines$6$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$3$lines$6$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$6
module top$pipeline$abc$lanes$3$lines$6$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$6$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$3$lines$6$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$3$lines$6$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$3$lines$6$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$6$line
module top$pipeline$abc$lanes$3$lines$6$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$6$line$one
module top$pipeline$abc$lanes$3$lines$6$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$6$line$ptr
module top$pipeline$abc$lanes$3$lines$6$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$3$lines$6$line$ram
module top$pipeline$abc$lanes$3$lines$6$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$6$line$rd_flipped
module top$pipeline$abc$lanes$3$lines$6$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$6$line_last
module top$pipeline$abc$lanes$3$lines$6$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$6$out
module top$pipeline$abc$lanes$3$lines$7(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  line$clock;
    reg  [31:0] line$data_in;
    reg  line$write_enable;
    wire  [31:0] line$data_out;
    reg  [15:0] line$last;
    reg  [15:0] line_last$d;
    wire  [15:0] line_last$q;
    reg  line_last$clock;
    reg  [31:0] out$d;
    wire  [31:0] out$q;
    reg  out$clock;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$7$line line(
        .clock(line$clock),
        .data_in(line$data_in),
        .write_enable(line$write_enable),
        .data_out(line$data_out),
        .last(line$last)
    );
    top$pipeline$abc$lanes$3$lines$7$line_last line_last(
        .d(line_last$d),
        .q(line_last$q),
        .clock(line_last$clock)
    );
    top$pipeline$abc$lanes$3$lines$7$out out(
        .d(out$d),
        .q(out$q),
        .clock(out$clock)
    );
    
    // Update code
    always @(*) begin
        line_last$clock = clock;
        out$clock = clock;
        line_last$d = line_last$q;
        out$d = out$q;
        line$clock = clock;
        line_last$d = last - 'h1;
        line$last = line_last$q;
        line$data_in = data_in;
        line$write_enable = write_enable;
        out$d = line$data_out;
        if (last == 'h0) begin
            out$d = out$q;
            if (write_enable) begin
                out$d = data_in & mask;
            end
        end
        data_out = out$q;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$7
module top$pipeline$abc$lanes$3$lines$7$line(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] data_in;
    input wire  write_enable;
    output reg  [31:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  flip = 16'h1;
    localparam  longest_last = 16'h4;
    localparam  single = 1'b0;
    localparam  mask = 'hffffffff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [31:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [31:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [15:0] rd_flipped$d;
    wire  [15:0] rd_flipped$q;
    reg  rd_flipped$clock;
    reg  [31:0] one$d;
    wire  [31:0] one$q;
    reg  one$clock;
    
    // Local signals
    reg  [15:0] rd;
    reg  [15:0] next;
    
    // Sub module instances
    top$pipeline$abc$lanes$3$lines$7$line$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$pipeline$abc$lanes$3$lines$7$line$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$pipeline$abc$lanes$3$lines$7$line$rd_flipped rd_flipped(
        .d(rd_flipped$d),
        .q(rd_flipped$q),
        .clock(rd_flipped$clock)
    );
    top$pipeline$abc$lanes$3$lines$7$line$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    
    // Update code
    reg  [31:0] data_out_pass;
    always @(*) begin
        ptr$clock = clock;
        rd_flipped$clock = clock;
        one$clock = clock;
        ptr$d = ptr$q;
        rd_flipped$d = rd_flipped$q;
        one$d = one$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        rd = rd_flipped$q ^ flip;
        next = rd + 'h1;
        if ((rd >= last) | (rd >= longest_last)) begin
            next = 'h0;
        end
        rd_flipped$d = next ^ flip;
        ptr$d = rd;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & ~single;
        ram$read_address = rd;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        if (single | (last == 'h0)) begin
            data_out_pass = one$q;
        end
        else begin
            data_out_pass = ram$read_data;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$pipeline$abc$lanes$3$lines$7$line
module top$pipeline$abc$lanes$3$lines$7$line$one(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$7$line$one
module top$pipeline$abc$lanes$3$lines$7$line$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$7$line$ptr
module top$pipeline$abc$lanes$3$lines$7$line$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    (* ram_style = "distributed" *)
    reg [31:0] mem[4:0];
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address[2:0]];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address[2:0]] <= write_data;
       end
    end
endmodule // top$pipeline$abc$lanes$3$lines$7$line$ram
module top$pipeline$abc$lanes$3$lines$7$line$rd_flipped(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$7$line$rd_flipped
module top$pipeline$abc$lanes$3$lines$7$line_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$7$line_last
module top$pipeline$abc$lanes$3$lines$7$out(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$lines$7$out
module top$pipeline$abc$lanes$3$one$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$one$0
module top$pipeline$abc$lanes$3$one$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$one$1
module top$pipeline$abc$lanes$3$one$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$one$2
module top$pipeline$abc$lanes$3$one$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$one$3
module top$pipeline$abc$lanes$3$one$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$one$4
module top$pipeline$abc$lanes$3$one$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$one$5
module top$pipeline$abc$lanes$3$one$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$one$6
module top$pipeline$abc$lanes$3$one$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$one$7
module top$pipeline$abc$lanes$3$one$8(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$one$8
module top$pipeline$abc$lanes$3$two$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$two$0
module top$pipeline$abc$lanes$3$two$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$two$1
module top$pipeline$abc$lanes$3$two$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$two$2
module top$pipeline$abc$lanes$3$two$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$two$3
module top$pipeline$abc$lanes$3$two$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$two$4
module top$pipeline$abc$lanes$3$two$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$two$5
module top$pipeline$abc$lanes$3$two$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$two$6
module top$pipeline$abc$lanes$3$two$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$two$7
module top$pipeline$abc$lanes$3$two$8(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$abc$lanes$3$two$8
