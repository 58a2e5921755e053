module top$flush(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$flush
module top$lanes$0(clock,host_write,host_address,host_data,dims,beats,order,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,res_beat,res_valid,res,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [63:0] dims;
    input wire  [63:0] beats;
    input wire  [63:0] order;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  res_beat;
    output reg  res_valid;
    output reg  [63:0] res;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Constant declarations
    localparam  coord_mask = 16'hff;
    
    // Stub signals
    reg  feed$clock;
    reg  [63:0] feed$beats;
    reg  feed$beat_valid;
    reg  [15:0] feed$value;
    reg  [15:0] feed$x;
    reg  [15:0] feed$y;
    reg  feed$pad;
    reg  feed$invalid;
    reg  feed$halo;
    reg  feed$sr;
    reg  feed$er;
    reg  [15:0] feed$base_x;
    reg  [15:0] feed$base_y;
    reg  [2:0] feed$face;
    reg  feed$at_edge;
    reg  feed$dx_neg;
    reg  [15:0] feed$dx_mag;
    reg  feed$dy_neg;
    reg  [15:0] feed$dy_mag;
    reg  [15:0] feed$g_from_left_xm;
    reg  [15:0] feed$g_from_left_ym;
    reg  [15:0] feed$g_from_left_zm;
    reg  [15:0] feed$g_from_right_xp;
    reg  [15:0] feed$g_from_right_yp;
    reg  [15:0] feed$g_from_right_zp;
    wire  [15:0] feed$g_to_right_xm;
    wire  [15:0] feed$g_to_right_ym;
    wire  [15:0] feed$g_to_right_zm;
    wire  [15:0] feed$g_to_left_xp;
    wire  [15:0] feed$g_to_left_yp;
    wire  [15:0] feed$g_to_left_zp;
    wire  feed$o_valid;
    wire  [15:0] feed$o_value;
    wire  [15:0] feed$o_x;
    wire  [15:0] feed$o_y;
    wire  feed$o_pad;
    wire  feed$o_invalid;
    wire  feed$o_sr;
    wire  feed$o_er;
    wire  feed$o_edge;
    wire  [2:0] feed$o_face;
    wire  [15:0] feed$o_base_x;
    wire  [15:0] feed$o_base_y;
    wire  feed$o_dx_neg;
    wire  [15:0] feed$o_dx_mag;
    wire  feed$o_dy_neg;
    wire  [15:0] feed$o_dy_mag;
    wire  feed$gx_neg;
    wire  [15:0] feed$gx_mag;
    wire  feed$gy_neg;
    wire  [15:0] feed$gy_mag;
    wire  feed$gz_neg;
    wire  [15:0] feed$gz_mag;
    reg  shader$clock;
    reg  shader$host_write;
    reg  [23:0] shader$host_address;
    reg  [63:0] shader$host_data;
    reg  [15:0] shader$value;
    reg  shader$invalid;
    reg  shader$at_edge;
    reg  shader$gx_neg;
    reg  [31:0] shader$gx_mag;
    reg  shader$gy_neg;
    reg  [31:0] shader$gy_mag;
    reg  shader$gz_neg;
    reg  [31:0] shader$gz_mag;
    wire  [31:0] shader$r;
    wire  [15:0] shader$g;
    wire  [15:0] shader$b;
    wire  [15:0] shader$a;
    wire  shader$valid;
    reg  ctl$clock;
    reg  ctl$valid;
    reg  ctl$er;
    reg  ctl$pad;
    reg  [15:0] ctl$base_x;
    reg  [15:0] ctl$base_y;
    reg  [2:0] ctl$face;
    reg  [15:0] ctl$x;
    reg  [15:0] ctl$y;
    reg  ctl$sr;
    reg  ctl$dx_neg;
    reg  [15:0] ctl$dx_mag;
    reg  ctl$dy_neg;
    reg  [15:0] ctl$dy_mag;
    reg  [63:0] ctl$dims;
    reg  [15:0] ctl$coord_mask;
    wire  [15:0] ctl$x_t;
    wire  [15:0] ctl$dx_mag_t;
    wire  [15:0] ctl$dy_mag_t;
    wire  [6:0] ctl$sel_t$0;
    wire  [6:0] ctl$sel_t$1;
    wire  [6:0] ctl$sel_t$2;
    wire  [6:0] ctl$sel_t$3;
    wire  ctl$res_beat;
    wire  ctl$res_valid;
    wire  ctl$px_valid;
    wire  [15:0] ctl$px_x;
    wire  [15:0] ctl$px_y;
    wire  [2:0] ctl$px_face;
    reg  taps$clock;
    reg  [63:0] taps$beats;
    reg  [15:0] taps$x;
    reg  [63:0] taps$res;
    reg  taps$res_beat;
    wire  [63:0] taps$t0s0;
    reg  [63:0] taps$t0i1;
    wire  [63:0] taps$t1s0;
    wire  [63:0] taps$t1s1;
    reg  [63:0] taps$t1i1;
    reg  [63:0] taps$t1i2;
    wire  [63:0] taps$t3s0;
    wire  [63:0] taps$t3s1;
    reg  [63:0] taps$t3i1;
    reg  [63:0] taps$t3i2;
    wire  [63:0] taps$t5s0;
    wire  [63:0] taps$t5s1;
    wire  [63:0] taps$t5s2;
    reg  [63:0] taps$t5i1;
    reg  [63:0] taps$t5i2;
    reg  [63:0] taps$t5i3;
    wire  [63:0] taps$t6s0;
    reg  [63:0] taps$t6i1;
    wire  [63:0] taps$t7s0;
    reg  [63:0] taps$t7i1;
    wire  [63:0] taps$t8s0;
    reg  [63:0] taps$t8i1;
    reg  [63:0] taps$t8il;
    wire  [63:0] taps$a$0;
    wire  [63:0] taps$a$1;
    wire  [63:0] taps$a$2;
    wire  [63:0] taps$a$3;
    wire  [63:0] taps$a$4;
    wire  [63:0] taps$a$5;
    wire  [63:0] taps$a$6;
    wire  [63:0] taps$a$7;
    wire  [63:0] taps$a$8;
    reg  [63:0] cells$a$0;
    reg  [63:0] cells$a$1;
    reg  [63:0] cells$a$2;
    reg  [63:0] cells$a$3;
    reg  [63:0] cells$a$4;
    reg  [63:0] cells$a$5;
    reg  [63:0] cells$a$6;
    reg  [63:0] cells$a$7;
    reg  [63:0] cells$a$8;
    reg  [6:0] cells$sel$0;
    reg  [6:0] cells$sel$1;
    reg  [6:0] cells$sel$2;
    reg  [6:0] cells$sel$3;
    wire  [31:0] cells$c00$0;
    wire  [31:0] cells$c00$1;
    wire  [31:0] cells$c00$2;
    wire  [31:0] cells$c00$3;
    wire  [31:0] cells$c10$0;
    wire  [31:0] cells$c10$1;
    wire  [31:0] cells$c10$2;
    wire  [31:0] cells$c10$3;
    wire  [31:0] cells$c01$0;
    wire  [31:0] cells$c01$1;
    wire  [31:0] cells$c01$2;
    wire  [31:0] cells$c01$3;
    wire  [31:0] cells$c11$0;
    wire  [31:0] cells$c11$1;
    wire  [31:0] cells$c11$2;
    wire  [31:0] cells$c11$3;
    reg  [63:0] cells$order;
    reg  bilinear$clock;
    reg  [31:0] bilinear$c00$0;
    reg  [31:0] bilinear$c00$1;
    reg  [31:0] bilinear$c00$2;
    reg  [31:0] bilinear$c00$3;
    reg  [31:0] bilinear$c10$0;
    reg  [31:0] bilinear$c10$1;
    reg  [31:0] bilinear$c10$2;
    reg  [31:0] bilinear$c10$3;
    reg  [31:0] bilinear$c01$0;
    reg  [31:0] bilinear$c01$1;
    reg  [31:0] bilinear$c01$2;
    reg  [31:0] bilinear$c01$3;
    reg  [31:0] bilinear$c11$0;
    reg  [31:0] bilinear$c11$1;
    reg  [31:0] bilinear$c11$2;
    reg  [31:0] bilinear$c11$3;
    reg  [15:0] bilinear$wx;
    reg  [15:0] bilinear$wy;
    wire  [31:0] bilinear$out$0;
    wire  [31:0] bilinear$out$1;
    wire  [31:0] bilinear$out$2;
    wire  [31:0] bilinear$out$3;
    reg  compositor$clock;
    reg  [31:0] compositor$acc_r;
    reg  [15:0] compositor$acc_g;
    reg  [15:0] compositor$acc_b;
    reg  [15:0] compositor$acc_a;
    reg  [31:0] compositor$new_r;
    reg  [15:0] compositor$new_g;
    reg  [15:0] compositor$new_b;
    reg  [15:0] compositor$new_a;
    reg  compositor$new_valid;
    wire  [31:0] compositor$out_r;
    wire  [15:0] compositor$out_g;
    wire  [15:0] compositor$out_b;
    wire  [15:0] compositor$out_a;
    reg  [63:0] compositor$order;
    
    // Sub module instances
    top$lanes$0$feed feed(
        .clock(feed$clock),
        .beats(feed$beats),
        .beat_valid(feed$beat_valid),
        .value(feed$value),
        .x(feed$x),
        .y(feed$y),
        .pad(feed$pad),
        .invalid(feed$invalid),
        .halo(feed$halo),
        .sr(feed$sr),
        .er(feed$er),
        .base_x(feed$base_x),
        .base_y(feed$base_y),
        .face(feed$face),
        .at_edge(feed$at_edge),
        .dx_neg(feed$dx_neg),
        .dx_mag(feed$dx_mag),
        .dy_neg(feed$dy_neg),
        .dy_mag(feed$dy_mag),
        .g_from_left_xm(feed$g_from_left_xm),
        .g_from_left_ym(feed$g_from_left_ym),
        .g_from_left_zm(feed$g_from_left_zm),
        .g_from_right_xp(feed$g_from_right_xp),
        .g_from_right_yp(feed$g_from_right_yp),
        .g_from_right_zp(feed$g_from_right_zp),
        .g_to_right_xm(feed$g_to_right_xm),
        .g_to_right_ym(feed$g_to_right_ym),
        .g_to_right_zm(feed$g_to_right_zm),
        .g_to_left_xp(feed$g_to_left_xp),
        .g_to_left_yp(feed$g_to_left_yp),
        .g_to_left_zp(feed$g_to_left_zp),
        .o_valid(feed$o_valid),
        .o_value(feed$o_value),
        .o_x(feed$o_x),
        .o_y(feed$o_y),
        .o_pad(feed$o_pad),
        .o_invalid(feed$o_invalid),
        .o_sr(feed$o_sr),
        .o_er(feed$o_er),
        .o_edge(feed$o_edge),
        .o_face(feed$o_face),
        .o_base_x(feed$o_base_x),
        .o_base_y(feed$o_base_y),
        .o_dx_neg(feed$o_dx_neg),
        .o_dx_mag(feed$o_dx_mag),
        .o_dy_neg(feed$o_dy_neg),
        .o_dy_mag(feed$o_dy_mag),
        .gx_neg(feed$gx_neg),
        .gx_mag(feed$gx_mag),
        .gy_neg(feed$gy_neg),
        .gy_mag(feed$gy_mag),
        .gz_neg(feed$gz_neg),
        .gz_mag(feed$gz_mag)
    );
    top$lanes$0$shader shader(
        .clock(shader$clock),
        .host_write(shader$host_write),
        .host_address(shader$host_address),
        .host_data(shader$host_data),
        .value(shader$value),
        .invalid(shader$invalid),
        .at_edge(shader$at_edge),
        .gx_neg(shader$gx_neg),
        .gx_mag(shader$gx_mag),
        .gy_neg(shader$gy_neg),
        .gy_mag(shader$gy_mag),
        .gz_neg(shader$gz_neg),
        .gz_mag(shader$gz_mag),
        .r(shader$r),
        .g(shader$g),
        .b(shader$b),
        .a(shader$a),
        .valid(shader$valid)
    );
    top$lanes$0$ctl ctl(
        .clock(ctl$clock),
        .valid(ctl$valid),
        .er(ctl$er),
        .pad(ctl$pad),
        .base_x(ctl$base_x),
        .base_y(ctl$base_y),
        .face(ctl$face),
        .x(ctl$x),
        .y(ctl$y),
        .sr(ctl$sr),
        .dx_neg(ctl$dx_neg),
        .dx_mag(ctl$dx_mag),
        .dy_neg(ctl$dy_neg),
        .dy_mag(ctl$dy_mag),
        .dims(ctl$dims),
        .coord_mask(ctl$coord_mask),
        .x_t(ctl$x_t),
        .dx_mag_t(ctl$dx_mag_t),
        .dy_mag_t(ctl$dy_mag_t),
        .sel_t$0(ctl$sel_t$0),
        .sel_t$1(ctl$sel_t$1),
        .sel_t$2(ctl$sel_t$2),
        .sel_t$3(ctl$sel_t$3),
        .res_beat(ctl$res_beat),
        .res_valid(ctl$res_valid),
        .px_valid(ctl$px_valid),
        .px_x(ctl$px_x),
        .px_y(ctl$px_y),
        .px_face(ctl$px_face)
    );
    top$lanes$0$taps taps(
        .clock(taps$clock),
        .beats(taps$beats),
        .x(taps$x),
        .res(taps$res),
        .res_beat(taps$res_beat),
        .t0s0(taps$t0s0),
        .t0i1(taps$t0i1),
        .t1s0(taps$t1s0),
        .t1s1(taps$t1s1),
        .t1i1(taps$t1i1),
        .t1i2(taps$t1i2),
        .t3s0(taps$t3s0),
        .t3s1(taps$t3s1),
        .t3i1(taps$t3i1),
        .t3i2(taps$t3i2),
        .t5s0(taps$t5s0),
        .t5s1(taps$t5s1),
        .t5s2(taps$t5s2),
        .t5i1(taps$t5i1),
        .t5i2(taps$t5i2),
        .t5i3(taps$t5i3),
        .t6s0(taps$t6s0),
        .t6i1(taps$t6i1),
        .t7s0(taps$t7s0),
        .t7i1(taps$t7i1),
        .t8s0(taps$t8s0),
        .t8i1(taps$t8i1),
        .t8il(taps$t8il),
        .a$0(taps$a$0),
        .a$1(taps$a$1),
        .a$2(taps$a$2),
        .a$3(taps$a$3),
        .a$4(taps$a$4),
        .a$5(taps$a$5),
        .a$6(taps$a$6),
        .a$7(taps$a$7),
        .a$8(taps$a$8)
    );
    top$lanes$0$cells cells(
        .a$0(cells$a$0),
        .a$1(cells$a$1),
        .a$2(cells$a$2),
        .a$3(cells$a$3),
        .a$4(cells$a$4),
        .a$5(cells$a$5),
        .a$6(cells$a$6),
        .a$7(cells$a$7),
        .a$8(cells$a$8),
        .sel$0(cells$sel$0),
        .sel$1(cells$sel$1),
        .sel$2(cells$sel$2),
        .sel$3(cells$sel$3),
        .c00$0(cells$c00$0),
        .c00$1(cells$c00$1),
        .c00$2(cells$c00$2),
        .c00$3(cells$c00$3),
        .c10$0(cells$c10$0),
        .c10$1(cells$c10$1),
        .c10$2(cells$c10$2),
        .c10$3(cells$c10$3),
        .c01$0(cells$c01$0),
        .c01$1(cells$c01$1),
        .c01$2(cells$c01$2),
        .c01$3(cells$c01$3),
        .c11$0(cells$c11$0),
        .c11$1(cells$c11$1),
        .c11$2(cells$c11$2),
        .c11$3(cells$c11$3),
        .order(cells$order)
    );
    top$lanes$0$bilinear bilinear(
        .clock(bilinear$clock),
        .c00$0(bilinear$c00$0),
        .c00$1(bilinear$c00$1),
        .c00$2(bilinear$c00$2),
        .c00$3(bilinear$c00$3),
        .c10$0(bilinear$c10$0),
        .c10$1(bilinear$c10$1),
        .c10$2(bilinear$c10$2),
        .c10$3(bilinear$c10$3),
        .c01$0(bilinear$c01$0),
        .c01$1(bilinear$c01$1),
        .c01$2(bilinear$c01$2),
        .c01$3(bilinear$c01$3),
        .c11$0(bilinear$c11$0),
        .c11$1(bilinear$c11$1),
        .c11$2(bilinear$c11$2),
        .c11$3(bilinear$c11$3),
        .wx(bilinear$wx),
        .wy(bilinear$wy),
        .out$0(bilinear$out$0),
        .out$1(bilinear$out$1),
        .out$2(bilinear$out$2),
        .out$3(bilinear$out$3)
    );
    top$lanes$0$compositor compositor(
        .clock(compositor$clock),
        .acc_r(compositor$acc_r),
        .acc_g(compositor$acc_g),
        .acc_b(compositor$acc_b),
        .acc_a(compositor$acc_a),
        .new_r(compositor$new_r),
        .new_g(compositor$new_g),
        .new_b(compositor$new_b),
        .new_a(compositor$new_a),
        .new_valid(compositor$new_valid),
        .out_r(compositor$out_r),
        .out_g(compositor$out_g),
        .out_b(compositor$out_b),
        .out_a(compositor$out_a),
        .order(compositor$order)
    );
    
    // Update code
    always @(*) begin
        feed$clock = clock;
        feed$beats = beats;
        feed$beat_valid = beat_valid;
        feed$value = value;
        feed$x = x;
        feed$y = y;
        feed$pad = pad;
        feed$invalid = invalid;
        feed$halo = halo;
        feed$sr = sr;
        feed$er = er;
        feed$base_x = base_x;
        feed$base_y = base_y;
        feed$face = face;
        feed$at_edge = at_edge;
        feed$dx_neg = dx_neg;
        feed$dx_mag = dx_mag;
        feed$dy_neg = dy_neg;
        feed$dy_mag = dy_mag;
        feed$g_from_left_xm = g_from_left_xm;
        feed$g_from_left_ym = g_from_left_ym;
        feed$g_from_left_zm = g_from_left_zm;
        feed$g_from_right_xp = g_from_right_xp;
        feed$g_from_right_yp = g_from_right_yp;
        feed$g_from_right_zp = g_from_right_zp;
        g_to_right_xm = feed$g_to_right_xm;
        g_to_right_ym = feed$g_to_right_ym;
        g_to_right_zm = feed$g_to_right_zm;
        g_to_left_xp = feed$g_to_left_xp;
        g_to_left_yp = feed$g_to_left_yp;
        g_to_left_zp = feed$g_to_left_zp;
        shader$clock = clock;
        shader$host_write = host_write;
        shader$host_address = host_address;
        shader$host_data = host_data;
        shader$value = feed$o_value;
        shader$invalid = feed$o_invalid;
        shader$at_edge = feed$o_edge;
        shader$gx_neg = feed$gx_neg;
        shader$gx_mag = 32'(feed$gx_mag);
        shader$gy_neg = feed$gy_neg;
        shader$gy_mag = 32'(feed$gy_mag);
        shader$gz_neg = feed$gz_neg;
        shader$gz_mag = 32'(feed$gz_mag);
        ctl$clock = clock;
        ctl$valid = feed$o_valid;
        ctl$er = feed$o_er;
        ctl$pad = feed$o_pad;
        ctl$coord_mask = coord_mask;
        ctl$base_x = feed$o_base_x;
        ctl$base_y = feed$o_base_y;
        ctl$face = feed$o_face;
        ctl$x = feed$o_x;
        ctl$y = feed$o_y;
        ctl$sr = feed$o_sr;
        ctl$dx_neg = feed$o_dx_neg;
        ctl$dx_mag = feed$o_dx_mag;
        ctl$dy_neg = feed$o_dy_neg;
        ctl$dy_mag = feed$o_dy_mag;
        ctl$dims = dims;
        taps$clock = clock;
        taps$beats = beats;
        taps$x = ctl$x_t;
        t0s0 = taps$t0s0;
        taps$t0i1 = t0i1;
        t1s0 = taps$t1s0;
        t1s1 = taps$t1s1;
        taps$t1i1 = t1i1;
        taps$t1i2 = t1i2;
        t3s0 = taps$t3s0;
        t3s1 = taps$t3s1;
        taps$t3i1 = t3i1;
        taps$t3i2 = t3i2;
        t5s0 = taps$t5s0;
        t5s1 = taps$t5s1;
        t5s2 = taps$t5s2;
        taps$t5i1 = t5i1;
        taps$t5i2 = t5i2;
        taps$t5i3 = t5i3;
        t6s0 = taps$t6s0;
        taps$t6i1 = t6i1;
        t7s0 = taps$t7s0;
        taps$t7i1 = t7i1;
        t8s0 = taps$t8s0;
        taps$t8i1 = t8i1;
        taps$t8il = t8il;
        cells$a$0 = taps$a$0;
        cells$a$1 = taps$a$1;
        cells$a$2 = taps$a$2;
        cells$a$3 = taps$a$3;
        cells$a$4 = taps$a$4;
        cells$a$5 = taps$a$5;
        cells$a$6 = taps$a$6;
        cells$a$7 = taps$a$7;
        cells$a$8 = taps$a$8;
        cells$order = order;
        cells$sel$0 = ctl$sel_t$0;
        cells$sel$1 = ctl$sel_t$1;
        cells$sel$2 = ctl$sel_t$2;
        cells$sel$3 = ctl$sel_t$3;
        bilinear$clock = clock;
        bilinear$c00$0 = cells$c00$0;
        bilinear$c10$0 = cells$c10$0;
        bilinear$c01$0 = cells$c01$0;
        bilinear$c11$0 = cells$c11$0;
        bilinear$c00$1 = cells$c00$1;
        bilinear$c10$1 = cells$c10$1;
        bilinear$c01$1 = cells$c01$1;
        bilinear$c11$1 = cells$c11$1;
        bilinear$c00$2 = cells$c00$2;
        bilinear$c10$2 = cells$c10$2;
        bilinear$c01$2 = cells$c01$2;
        bilinear$c11$2 = cells$c11$2;
        bilinear$c00$3 = cells$c00$3;
        bilinear$c10$3 = cells$c10$3;
        bilinear$c01$3 = cells$c01$3;
        bilinear$c11$3 = cells$c11$3;
        bilinear$wx = ctl$dx_mag_t;
        bilinear$wy = ctl$dy_mag_t;
        compositor$clock = clock;
        compositor$order = order;
        compositor$acc_r = bilinear$out$0;
        compositor$acc_g = 16'(bilinear$out$1);
        compositor$acc_b = 16'(bilinear$out$2);
        compositor$acc_a = 16'(bilinear$out$3);
        compositor$new_r = shader$r;
        compositor$new_g = shader$g;
        compositor$new_b = shader$b;
        compositor$new_a = shader$a;
        compositor$new_valid = shader$valid;
        res = 64'(compositor$out_r) | (64'(compositor$out_g) << 'h10) | (64'(compositor$out_b) << 'h20) | (64'(compositor$out_a) << 'h30);
        taps$res = res;
        taps$res_beat = ctl$res_beat;
        res_beat = ctl$res_beat;
        res_valid = ctl$res_valid;
        px_valid = ctl$px_valid;
        px_x = ctl$px_x;
        px_y = ctl$px_y;
        px_face = ctl$px_face;
    end
    
endmodule // top$lanes$0
module top$lanes$0$cells(a$0,a$1,a$2,a$3,a$4,a$5,a$6,a$7,a$8,sel$0,sel$1,sel$2,sel$3,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,order);
    
    // Module arguments
    input wire  [63:0] a$0;
    input wire  [63:0] a$1;
    input wire  [63:0] a$2;
    input wire  [63:0] a$3;
    input wire  [63:0] a$4;
    input wire  [63:0] a$5;
    input wire  [63:0] a$6;
    input wire  [63:0] a$7;
    input wire  [63:0] a$8;
    input wire  [6:0] sel$0;
    input wire  [6:0] sel$1;
    input wire  [6:0] sel$2;
    input wire  [6:0] sel$3;
    output reg  [31:0] c00$0;
    output reg  [31:0] c00$1;
    output reg  [31:0] c00$2;
    output reg  [31:0] c00$3;
    output reg  [31:0] c10$0;
    output reg  [31:0] c10$1;
    output reg  [31:0] c10$2;
    output reg  [31:0] c10$3;
    output reg  [31:0] c01$0;
    output reg  [31:0] c01$1;
    output reg  [31:0] c01$2;
    output reg  [31:0] c01$3;
    output reg  [31:0] c11$0;
    output reg  [31:0] c11$1;
    output reg  [31:0] c11$2;
    output reg  [31:0] c11$3;
    input wire  [63:0] order;
    
    // Constant declarations
    localparam  vmax = 64'hff;
    localparam  r_mask = 64'hffff;
    localparam  gba_mask = 64'hffff;
    
    // Local signals
    reg  [63:0] reset;
    reg  [63:0] w00$0;
    reg  [63:0] w00$1;
    reg  [63:0] w00$2;
    reg  [63:0] w00$3;
    reg  [63:0] w10$0;
    reg  [63:0] w10$1;
    reg  [63:0] w10$2;
    reg  [63:0] w10$3;
    reg  [63:0] w01$0;
    reg  [63:0] w01$1;
    reg  [63:0] w01$2;
    reg  [63:0] w01$3;
    reg  [63:0] w11$0;
    reg  [63:0] w11$1;
    reg  [63:0] w11$2;
    reg  [63:0] w11$3;
    
    // Update code
    always @(*) begin
        reset = 'h0;
        if (order['h1]) begin
            reset = vmax;
        end
        w00$0 = a$0;
        w10$0 = a$0;
        w01$0 = a$0;
        if (sel$0['h2]) begin
            if (sel$0['h1]) begin
                w10$0 = a$2;
            end
            else begin
                w10$0 = a$1;
            end
        end
        if (sel$0['h4]) begin
            if (sel$0['h3]) begin
                w01$0 = a$4;
            end
            else begin
                w01$0 = a$3;
            end
        end
        w11$0 = w01$0;
        if (sel$0['h2]) begin
            w11$0 = w10$0;
            if (sel$0['h4]) begin
                if (sel$0['h1]) begin
                    if (sel$0['h3]) begin
                        w11$0 = a$8;
                    end
                    else begin
                        w11$0 = a$6;
                    end
                end
                else if (sel$0['h3]) begin
                    w11$0 = a$7;
                end
                else begin
                    w11$0 = a$5;
                end
            end
        end
        if (sel$0['h5]) begin
            w10$0 = reset;
            w11$0 = reset;
        end
        if (sel$0['h6]) begin
            w01$0 = reset;
            w11$0 = reset;
        end
        if (sel$0['h0]) begin
            w00$0 = reset;
            w10$0 = reset;
            w01$0 = reset;
            w11$0 = reset;
        end
        w00$1 = a$0;
        w10$1 = a$0;
        w01$1 = a$0;
        if (sel$1['h2]) begin
            if (sel$1['h1]) begin
                w10$1 = a$2;
            end
            else begin
                w10$1 = a$1;
            end
        end
        if (sel$1['h4]) begin
            if (sel$1['h3]) begin
                w01$1 = a$4;
            end
            else begin
                w01$1 = a$3;
            end
        end
        w11$1 = w01$1;
        if (sel$1['h2]) begin
            w11$1 = w10$1;
            if (sel$1['h4]) begin
                if (sel$1['h1]) begin
                    if (sel$1['h3]) begin
                        w11$1 = a$8;
                    end
                    else begin
                        w11$1 = a$6;
                    end
                end
                else if (sel$1['h3]) begin
                    w11$1 = a$7;
                end
                else begin
                    w11$1 = a$5;
                end
            end
        end
        if (sel$1['h5]) begin
            w10$1 = reset;
            w11$1 = reset;
        end
        if (sel$1['h6]) begin
            w01$1 = reset;
            w11$1 = reset;
        end
        if (sel$1['h0]) begin
            w00$1 = reset;
            w10$1 = reset;
            w01$1 = reset;
            w11$1 = reset;
        end
        w00$2 = a$0;
        w10$2 = a$0;
        w01$2 = a$0;
        if (sel$2['h2]) begin
            if (sel$2['h1]) begin
                w10$2 = a$2;
            end
            else begin
                w10$2 = a$1;
            end
        end
        if (sel$2['h4]) begin
            if (sel$2['h3]) begin
                w01$2 = a$4;
            end
            else begin
                w01$2 = a$3;
            end
        end
        w11$2 = w01$2;
        if (sel$2['h2]) begin
            w11$2 = w10$2;
            if (sel$2['h4]) begin
                if (sel$2['h1]) begin
                    if (sel$2['h3]) begin
                        w11$2 = a$8;
                    end
                    else begin
                        w11$2 = a$6;
                    end
                end
                else if (sel$2['h3]) begin
                    w11$2 = a$7;
                end
                else begin
                    w11$2 = a$5;
                end
            end
        end
        if (sel$2['h5]) begin
            w10$2 = reset;
            w11$2 = reset;
        end
        if (sel$2['h6]) begin
            w01$2 = reset;
            w11$2 = reset;
        end
        if (sel$2['h0]) begin
            w00$2 = reset;
            w10$2 = reset;
            w01$2 = reset;
            w11$2 = reset;
        end
        w00$3 = a$0;
        w10$3 = a$0;
        w01$3 = a$0;
        if (sel$3['h2]) begin
            if (sel$3['h1]) begin
                w10$3 = a$2;
            end
            else begin
                w10$3 = a$1;
            end
        end
        if (sel$3['h4]) begin
            if (sel$3['h3]) begin
                w01$3 = a$4;
            end
            else begin
                w01$3 = a$3;
            end
        end
        w11$3 = w01$3;
        if (sel$3['h2]) begin
            w11$3 = w10$3;
            if (sel$3['h4]) begin
                if (sel$3['h1]) begin
                    if (sel$3['h3]) begin
                        w11$3 = a$8;
                    end
                    else begin
                        w11$3 = a$6;
                    end
                end
                else if (sel$3['h3]) begin
                    w11$3 = a$7;
                end
                else begin
                    w11$3 = a$5;
                end
            end
        end
        if (sel$3['h5]) begin
            w10$3 = reset;
            w11$3 = reset;
        end
        if (sel$3['h6]) begin
            w01$3 = reset;
            w11$3 = reset;
        end
        if (sel$3['h0]) begin
            w00$3 = reset;
            w10$3 = reset;
            w01$3 = reset;
            w11$3 = reset;
        end
        c00$0 = 32'(w00$0 & r_mask);
        c00$1 = 32'((w00$1 >> 'h10) & gba_mask);
        c00$2 = 32'((w00$2 >> 'h20) & gba_mask);
        c00$3 = 32'((w00$3 >> 'h30) & gba_mask);
        c10$0 = 32'(w10$0 & r_mask);
        c10$1 = 32'((w10$1 >> 'h10) & gba_mask);
        c10$2 = 32'((w10$2 >> 'h20) & gba_mask);
        c10$3 = 32'((w10$3 >> 'h30) & gba_mask);
        c01$0 = 32'(w01$0 & r_mask);
        c01$1 = 32'((w01$1 >> 'h10) & gba_mask);
        c01$2 = 32'((w01$2 >> 'h20) & gba_mask);
        c01$3 = 32'((w01$3 >> 'h30) & gba_mask);
        c11$0 = 32'(w11$0 & r_mask);
        c11$1 = 32'((w11$1 >> 'h10) & gba_mask);
        c11$2 = 32'((w11$2 >> 'h20) & gba_mask);
        c11$3 = 32'((w11$3 >> 'h30) & gba_mask);
    end
    
endmodule // top$lanes$0$cells
module top$lanes$0$ctl(clock,valid,er,pad,base_x,base_y,face,x,y,sr,dx_neg,dx_mag,dy_neg,dy_mag,dims,coord_mask,x_t,dx_mag_t,dy_mag_t,sel_t$0,sel_t$1,sel_t$2,sel_t$3,res_beat,res_valid,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  valid;
    input wire  er;
    input wire  pad;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  sr;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [63:0] dims;
    input wire  [15:0] coord_mask;
    output reg  [15:0] x_t;
    output reg  [15:0] dx_mag_t;
    output reg  [15:0] dy_mag_t;
    output reg  [6:0] sel_t$0;
    output reg  [6:0] sel_t$1;
    output reg  [6:0] sel_t$2;
    output reg  [6:0] sel_t$3;
    output reg  res_beat;
    output reg  res_valid;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Stub signals
    reg  [15:0] nx_last$d;
    wire  [15:0] nx_last$q;
    reg  nx_last$clock;
    reg  [15:0] ny_last$d;
    wire  [15:0] ny_last$q;
    reg  ny_last$clock;
    reg  [6:0] sel_q$0$d;
    wire  [6:0] sel_q$0$q;
    reg  sel_q$0$clock;
    reg  [6:0] sel_q$1$d;
    wire  [6:0] sel_q$1$q;
    reg  sel_q$1$clock;
    reg  [6:0] sel_q$2$d;
    wire  [6:0] sel_q$2$q;
    reg  sel_q$2$clock;
    reg  [6:0] sel_q$3$d;
    wire  [6:0] sel_q$3$q;
    reg  sel_q$3$clock;
    reg  [15:0] x_q$0$d;
    wire  [15:0] x_q$0$q;
    reg  x_q$0$clock;
    reg  [15:0] x_q$1$d;
    wire  [15:0] x_q$1$q;
    reg  x_q$1$clock;
    reg  [15:0] x_q$2$d;
    wire  [15:0] x_q$2$q;
    reg  x_q$2$clock;
    reg  [15:0] x_q$3$d;
    wire  [15:0] x_q$3$q;
    reg  x_q$3$clock;
    reg  [15:0] x_q$4$d;
    wire  [15:0] x_q$4$q;
    reg  x_q$4$clock;
    reg  [15:0] x_q$5$d;
    wire  [15:0] x_q$5$q;
    reg  x_q$5$clock;
    reg  [15:0] x_q$6$d;
    wire  [15:0] x_q$6$q;
    reg  x_q$6$clock;
    reg  [15:0] x_q$7$d;
    wire  [15:0] x_q$7$q;
    reg  x_q$7$clock;
    reg  [15:0] x_q$8$d;
    wire  [15:0] x_q$8$q;
    reg  x_q$8$clock;
    reg  [15:0] x_q$9$d;
    wire  [15:0] x_q$9$q;
    reg  x_q$9$clock;
    reg  [15:0] y_q$0$d;
    wire  [15:0] y_q$0$q;
    reg  y_q$0$clock;
    reg  [15:0] y_q$1$d;
    wire  [15:0] y_q$1$q;
    reg  y_q$1$clock;
    reg  [15:0] y_q$2$d;
    wire  [15:0] y_q$2$q;
    reg  y_q$2$clock;
    reg  [15:0] y_q$3$d;
    wire  [15:0] y_q$3$q;
    reg  y_q$3$clock;
    reg  [15:0] y_q$4$d;
    wire  [15:0] y_q$4$q;
    reg  y_q$4$clock;
    reg  [15:0] y_q$5$d;
    wire  [15:0] y_q$5$q;
    reg  y_q$5$clock;
    reg  [15:0] y_q$6$d;
    wire  [15:0] y_q$6$q;
    reg  y_q$6$clock;
    reg  [15:0] y_q$7$d;
    wire  [15:0] y_q$7$q;
    reg  y_q$7$clock;
    reg  [15:0] y_q$8$d;
    wire  [15:0] y_q$8$q;
    reg  y_q$8$clock;
    reg  sr_q$0$d;
    wire  sr_q$0$q;
    reg  sr_q$0$clock;
    reg  sr_q$1$d;
    wire  sr_q$1$q;
    reg  sr_q$1$clock;
    reg  sr_q$2$d;
    wire  sr_q$2$q;
    reg  sr_q$2$clock;
    reg  sr_q$3$d;
    wire  sr_q$3$q;
    reg  sr_q$3$clock;
    reg  sr_q$4$d;
    wire  sr_q$4$q;
    reg  sr_q$4$clock;
    reg  sr_q$5$d;
    wire  sr_q$5$q;
    reg  sr_q$5$clock;
    reg  sr_q$6$d;
    wire  sr_q$6$q;
    reg  sr_q$6$clock;
    reg  sr_q$7$d;
    wire  sr_q$7$q;
    reg  sr_q$7$clock;
    reg  sr_q$8$d;
    wire  sr_q$8$q;
    reg  sr_q$8$clock;
    reg  dxn_q$0$d;
    wire  dxn_q$0$q;
    reg  dxn_q$0$clock;
    reg  dxn_q$1$d;
    wire  dxn_q$1$q;
    reg  dxn_q$1$clock;
    reg  dxn_q$2$d;
    wire  dxn_q$2$q;
    reg  dxn_q$2$clock;
    reg  dxn_q$3$d;
    wire  dxn_q$3$q;
    reg  dxn_q$3$clock;
    reg  dxn_q$4$d;
    wire  dxn_q$4$q;
    reg  dxn_q$4$clock;
    reg  dxn_q$5$d;
    wire  dxn_q$5$q;
    reg  dxn_q$5$clock;
    reg  dxn_q$6$d;
    wire  dxn_q$6$q;
    reg  dxn_q$6$clock;
    reg  dxn_q$7$d;
    wire  dxn_q$7$q;
    reg  dxn_q$7$clock;
    reg  dxn_q$8$d;
    wire  dxn_q$8$q;
    reg  dxn_q$8$clock;
    reg  [15:0] dxm_q$0$d;
    wire  [15:0] dxm_q$0$q;
    reg  dxm_q$0$clock;
    reg  [15:0] dxm_q$1$d;
    wire  [15:0] dxm_q$1$q;
    reg  dxm_q$1$clock;
    reg  [15:0] dxm_q$2$d;
    wire  [15:0] dxm_q$2$q;
    reg  dxm_q$2$clock;
    reg  [15:0] dxm_q$3$d;
    wire  [15:0] dxm_q$3$q;
    reg  dxm_q$3$clock;
    reg  [15:0] dxm_q$4$d;
    wire  [15:0] dxm_q$4$q;
    reg  dxm_q$4$clock;
    reg  [15:0] dxm_q$5$d;
    wire  [15:0] dxm_q$5$q;
    reg  dxm_q$5$clock;
    reg  [15:0] dxm_q$6$d;
    wire  [15:0] dxm_q$6$q;
    reg  dxm_q$6$clock;
    reg  [15:0] dxm_q$7$d;
    wire  [15:0] dxm_q$7$q;
    reg  dxm_q$7$clock;
    reg  [15:0] dxm_q$8$d;
    wire  [15:0] dxm_q$8$q;
    reg  dxm_q$8$clock;
    reg  [15:0] dxm_q$9$d;
    wire  [15:0] dxm_q$9$q;
    reg  dxm_q$9$clock;
    reg  dyn_q$0$d;
    wire  dyn_q$0$q;
    reg  dyn_q$0$clock;
    reg  dyn_q$1$d;
    wire  dyn_q$1$q;
    reg  dyn_q$1$clock;
    reg  dyn_q$2$d;
    wire  dyn_q$2$q;
    reg  dyn_q$2$clock;
    reg  dyn_q$3$d;
    wire  dyn_q$3$q;
    reg  dyn_q$3$clock;
    reg  dyn_q$4$d;
    wire  dyn_q$4$q;
    reg  dyn_q$4$clock;
    reg  dyn_q$5$d;
    wire  dyn_q$5$q;
    reg  dyn_q$5$clock;
    reg  dyn_q$6$d;
    wire  dyn_q$6$q;
    reg  dyn_q$6$clock;
    reg  dyn_q$7$d;
    wire  dyn_q$7$q;
    reg  dyn_q$7$clock;
    reg  dyn_q$8$d;
    wire  dyn_q$8$q;
    reg  dyn_q$8$clock;
    reg  [15:0] dym_q$0$d;
    wire  [15:0] dym_q$0$q;
    reg  dym_q$0$clock;
    reg  [15:0] dym_q$1$d;
    wire  [15:0] dym_q$1$q;
    reg  dym_q$1$clock;
    reg  [15:0] dym_q$2$d;
    wire  [15:0] dym_q$2$q;
    reg  dym_q$2$clock;
    reg  [15:0] dym_q$3$d;
    wire  [15:0] dym_q$3$q;
    reg  dym_q$3$clock;
    reg  [15:0] dym_q$4$d;
    wire  [15:0] dym_q$4$q;
    reg  dym_q$4$clock;
    reg  [15:0] dym_q$5$d;
    wire  [15:0] dym_q$5$q;
    reg  dym_q$5$clock;
    reg  [15:0] dym_q$6$d;
    wire  [15:0] dym_q$6$q;
    reg  dym_q$6$clock;
    reg  [15:0] dym_q$7$d;
    wire  [15:0] dym_q$7$q;
    reg  dym_q$7$clock;
    reg  [15:0] dym_q$8$d;
    wire  [15:0] dym_q$8$q;
    reg  dym_q$8$clock;
    reg  [15:0] dym_q$9$d;
    wire  [15:0] dym_q$9$q;
    reg  dym_q$9$clock;
    reg  v_q$0$d;
    wire  v_q$0$q;
    reg  v_q$0$clock;
    reg  v_q$1$d;
    wire  v_q$1$q;
    reg  v_q$1$clock;
    reg  v_q$2$d;
    wire  v_q$2$q;
    reg  v_q$2$clock;
    reg  v_q$3$d;
    wire  v_q$3$q;
    reg  v_q$3$clock;
    reg  v_q$4$d;
    wire  v_q$4$q;
    reg  v_q$4$clock;
    reg  v_q$5$d;
    wire  v_q$5$q;
    reg  v_q$5$clock;
    reg  v_q$6$d;
    wire  v_q$6$q;
    reg  v_q$6$clock;
    reg  v_q$7$d;
    wire  v_q$7$q;
    reg  v_q$7$clock;
    reg  v_q$8$d;
    wire  v_q$8$q;
    reg  v_q$8$clock;
    reg  v_q$9$d;
    wire  v_q$9$q;
    reg  v_q$9$clock;
    reg  v_q$10$d;
    wire  v_q$10$q;
    reg  v_q$10$clock;
    reg  v_q$11$d;
    wire  v_q$11$q;
    reg  v_q$11$clock;
    reg  v_q$12$d;
    wire  v_q$12$q;
    reg  v_q$12$clock;
    reg  v_q$13$d;
    wire  v_q$13$q;
    reg  v_q$13$clock;
    reg  v_q$14$d;
    wire  v_q$14$q;
    reg  v_q$14$clock;
    reg  v_q$15$d;
    wire  v_q$15$q;
    reg  v_q$15$clock;
    reg  v_q$16$d;
    wire  v_q$16$q;
    reg  v_q$16$clock;
    reg  v_q$17$d;
    wire  v_q$17$q;
    reg  v_q$17$clock;
    reg  v_q$18$d;
    wire  v_q$18$q;
    reg  v_q$18$clock;
    reg  v_q$19$d;
    wire  v_q$19$q;
    reg  v_q$19$clock;
    reg  v_q$20$d;
    wire  v_q$20$q;
    reg  v_q$20$clock;
    reg  er_q$0$d;
    wire  er_q$0$q;
    reg  er_q$0$clock;
    reg  er_q$1$d;
    wire  er_q$1$q;
    reg  er_q$1$clock;
    reg  er_q$2$d;
    wire  er_q$2$q;
    reg  er_q$2$clock;
    reg  er_q$3$d;
    wire  er_q$3$q;
    reg  er_q$3$clock;
    reg  er_q$4$d;
    wire  er_q$4$q;
    reg  er_q$4$clock;
    reg  er_q$5$d;
    wire  er_q$5$q;
    reg  er_q$5$clock;
    reg  er_q$6$d;
    wire  er_q$6$q;
    reg  er_q$6$clock;
    reg  er_q$7$d;
    wire  er_q$7$q;
    reg  er_q$7$clock;
    reg  er_q$8$d;
    wire  er_q$8$q;
    reg  er_q$8$clock;
    reg  er_q$9$d;
    wire  er_q$9$q;
    reg  er_q$9$clock;
    reg  er_q$10$d;
    wire  er_q$10$q;
    reg  er_q$10$clock;
    reg  er_q$11$d;
    wire  er_q$11$q;
    reg  er_q$11$clock;
    reg  er_q$12$d;
    wire  er_q$12$q;
    reg  er_q$12$clock;
    reg  er_q$13$d;
    wire  er_q$13$q;
    reg  er_q$13$clock;
    reg  er_q$14$d;
    wire  er_q$14$q;
    reg  er_q$14$clock;
    reg  er_q$15$d;
    wire  er_q$15$q;
    reg  er_q$15$clock;
    reg  er_q$16$d;
    wire  er_q$16$q;
    reg  er_q$16$clock;
    reg  er_q$17$d;
    wire  er_q$17$q;
    reg  er_q$17$clock;
    reg  er_q$18$d;
    wire  er_q$18$q;
    reg  er_q$18$clock;
    reg  er_q$19$d;
    wire  er_q$19$q;
    reg  er_q$19$clock;
    reg  er_q$20$d;
    wire  er_q$20$q;
    reg  er_q$20$clock;
    reg  pad_q$0$d;
    wire  pad_q$0$q;
    reg  pad_q$0$clock;
    reg  pad_q$1$d;
    wire  pad_q$1$q;
    reg  pad_q$1$clock;
    reg  pad_q$2$d;
    wire  pad_q$2$q;
    reg  pad_q$2$clock;
    reg  pad_q$3$d;
    wire  pad_q$3$q;
    reg  pad_q$3$clock;
    reg  pad_q$4$d;
    wire  pad_q$4$q;
    reg  pad_q$4$clock;
    reg  pad_q$5$d;
    wire  pad_q$5$q;
    reg  pad_q$5$clock;
    reg  pad_q$6$d;
    wire  pad_q$6$q;
    reg  pad_q$6$clock;
    reg  pad_q$7$d;
    wire  pad_q$7$q;
    reg  pad_q$7$clock;
    reg  pad_q$8$d;
    wire  pad_q$8$q;
    reg  pad_q$8$clock;
    reg  pad_q$9$d;
    wire  pad_q$9$q;
    reg  pad_q$9$clock;
    reg  pad_q$10$d;
    wire  pad_q$10$q;
    reg  pad_q$10$clock;
    reg  pad_q$11$d;
    wire  pad_q$11$q;
    reg  pad_q$11$clock;
    reg  pad_q$12$d;
    wire  pad_q$12$q;
    reg  pad_q$12$clock;
    reg  pad_q$13$d;
    wire  pad_q$13$q;
    reg  pad_q$13$clock;
    reg  pad_q$14$d;
    wire  pad_q$14$q;
    reg  pad_q$14$clock;
    reg  pad_q$15$d;
    wire  pad_q$15$q;
    reg  pad_q$15$clock;
    reg  pad_q$16$d;
    wire  pad_q$16$q;
    reg  pad_q$16$clock;
    reg  pad_q$17$d;
    wire  pad_q$17$q;
    reg  pad_q$17$clock;
    reg  pad_q$18$d;
    wire  pad_q$18$q;
    reg  pad_q$18$clock;
    reg  pad_q$19$d;
    wire  pad_q$19$q;
    reg  pad_q$19$clock;
    reg  pad_q$20$d;
    wire  pad_q$20$q;
    reg  pad_q$20$clock;
    reg  [15:0] bx_q$0$d;
    wire  [15:0] bx_q$0$q;
    reg  bx_q$0$clock;
    reg  [15:0] bx_q$1$d;
    wire  [15:0] bx_q$1$q;
    reg  bx_q$1$clock;
    reg  [15:0] bx_q$2$d;
    wire  [15:0] bx_q$2$q;
    reg  bx_q$2$clock;
    reg  [15:0] bx_q$3$d;
    wire  [15:0] bx_q$3$q;
    reg  bx_q$3$clock;
    reg  [15:0] bx_q$4$d;
    wire  [15:0] bx_q$4$q;
    reg  bx_q$4$clock;
    reg  [15:0] bx_q$5$d;
    wire  [15:0] bx_q$5$q;
    reg  bx_q$5$clock;
    reg  [15:0] bx_q$6$d;
    wire  [15:0] bx_q$6$q;
    reg  bx_q$6$clock;
    reg  [15:0] bx_q$7$d;
    wire  [15:0] bx_q$7$q;
    reg  bx_q$7$clock;
    reg  [15:0] bx_q$8$d;
    wire  [15:0] bx_q$8$q;
    reg  bx_q$8$clock;
    reg  [15:0] bx_q$9$d;
    wire  [15:0] bx_q$9$q;
    reg  bx_q$9$clock;
    reg  [15:0] bx_q$10$d;
    wire  [15:0] bx_q$10$q;
    reg  bx_q$10$clock;
    reg  [15:0] bx_q$11$d;
    wire  [15:0] bx_q$11$q;
    reg  bx_q$11$clock;
    reg  [15:0] bx_q$12$d;
    wire  [15:0] bx_q$12$q;
    reg  bx_q$12$clock;
    reg  [15:0] bx_q$13$d;
    wire  [15:0] bx_q$13$q;
    reg  bx_q$13$clock;
    reg  [15:0] bx_q$14$d;
    wire  [15:0] bx_q$14$q;
    reg  bx_q$14$clock;
    reg  [15:0] bx_q$15$d;
    wire  [15:0] bx_q$15$q;
    reg  bx_q$15$clock;
    reg  [15:0] bx_q$16$d;
    wire  [15:0] bx_q$16$q;
    reg  bx_q$16$clock;
    reg  [15:0] bx_q$17$d;
    wire  [15:0] bx_q$17$q;
    reg  bx_q$17$clock;
    reg  [15:0] bx_q$18$d;
    wire  [15:0] bx_q$18$q;
    reg  bx_q$18$clock;
    reg  [15:0] bx_q$19$d;
    wire  [15:0] bx_q$19$q;
    reg  bx_q$19$clock;
    reg  [15:0] bx_q$20$d;
    wire  [15:0] bx_q$20$q;
    reg  bx_q$20$clock;
    reg  [15:0] by_q$0$d;
    wire  [15:0] by_q$0$q;
    reg  by_q$0$clock;
    reg  [15:0] by_q$1$d;
    wire  [15:0] by_q$1$q;
    reg  by_q$1$clock;
    reg  [15:0] by_q$2$d;
    wire  [15:0] by_q$2$q;
    reg  by_q$2$clock;
    reg  [15:0] by_q$3$d;
    wire  [15:0] by_q$3$q;
    reg  by_q$3$clock;
    reg  [15:0] by_q$4$d;
    wire  [15:0] by_q$4$q;
    reg  by_q$4$clock;
    reg  [15:0] by_q$5$d;
    wire  [15:0] by_q$5$q;
    reg  by_q$5$clock;
    reg  [15:0] by_q$6$d;
    wire  [15:0] by_q$6$q;
    reg  by_q$6$clock;
    reg  [15:0] by_q$7$d;
    wire  [15:0] by_q$7$q;
    reg  by_q$7$clock;
    reg  [15:0] by_q$8$d;
    wire  [15:0] by_q$8$q;
    reg  by_q$8$clock;
    reg  [15:0] by_q$9$d;
    wire  [15:0] by_q$9$q;
    reg  by_q$9$clock;
    reg  [15:0] by_q$10$d;
    wire  [15:0] by_q$10$q;
    reg  by_q$10$clock;
    reg  [15:0] by_q$11$d;
    wire  [15:0] by_q$11$q;
    reg  by_q$11$clock;
    reg  [15:0] by_q$12$d;
    wire  [15:0] by_q$12$q;
    reg  by_q$12$clock;
    reg  [15:0] by_q$13$d;
    wire  [15:0] by_q$13$q;
    reg  by_q$13$clock;
    reg  [15:0] by_q$14$d;
    wire  [15:0] by_q$14$q;
    reg  by_q$14$clock;
    reg  [15:0] by_q$15$d;
    wire  [15:0] by_q$15$q;
    reg  by_q$15$clock;
    reg  [15:0] by_q$16$d;
    wire  [15:0] by_q$16$q;
    reg  by_q$16$clock;
    reg  [15:0] by_q$17$d;
    wire  [15:0] by_q$17$q;
    reg  by_q$17$clock;
    reg  [15:0] by_q$18$d;
    wire  [15:0] by_q$18$q;
    reg  by_q$18$clock;
    reg  [15:0] by_q$19$d;
    wire  [15:0] by_q$19$q;
    reg  by_q$19$clock;
    reg  [15:0] by_q$20$d;
    wire  [15:0] by_q$20$q;
    reg  by_q$20$clock;
    reg  [2:0] face_q$0$d;
    wire  [2:0] face_q$0$q;
    reg  face_q$0$clock;
    reg  [2:0] face_q$1$d;
    wire  [2:0] face_q$1$q;
    reg  face_q$1$clock;
    reg  [2:0] face_q$2$d;
    wire  [2:0] face_q$2$q;
    reg  face_q$2$clock;
    reg  [2:0] face_q$3$d;
    wire  [2:0] face_q$3$q;
    reg  face_q$3$clock;
    reg  [2:0] face_q$4$d;
    wire  [2:0] face_q$4$q;
    reg  face_q$4$clock;
    reg  [2:0] face_q$5$d;
    wire  [2:0] face_q$5$q;
    reg  face_q$5$clock;
    reg  [2:0] face_q$6$d;
    wire  [2:0] face_q$6$q;
    reg  face_q$6$clock;
    reg  [2:0] face_q$7$d;
    wire  [2:0] face_q$7$q;
    reg  face_q$7$clock;
    reg  [2:0] face_q$8$d;
    wire  [2:0] face_q$8$q;
    reg  face_q$8$clock;
    reg  [2:0] face_q$9$d;
    wire  [2:0] face_q$9$q;
    reg  face_q$9$clock;
    reg  [2:0] face_q$10$d;
    wire  [2:0] face_q$10$q;
    reg  face_q$10$clock;
    reg  [2:0] face_q$11$d;
    wire  [2:0] face_q$11$q;
    reg  face_q$11$clock;
    reg  [2:0] face_q$12$d;
    wire  [2:0] face_q$12$q;
    reg  face_q$12$clock;
    reg  [2:0] face_q$13$d;
    wire  [2:0] face_q$13$q;
    reg  face_q$13$clock;
    reg  [2:0] face_q$14$d;
    wire  [2:0] face_q$14$q;
    reg  face_q$14$clock;
    reg  [2:0] face_q$15$d;
    wire  [2:0] face_q$15$q;
    reg  face_q$15$clock;
    reg  [2:0] face_q$16$d;
    wire  [2:0] face_q$16$q;
    reg  face_q$16$clock;
    reg  [2:0] face_q$17$d;
    wire  [2:0] face_q$17$q;
    reg  face_q$17$clock;
    reg  [2:0] face_q$18$d;
    wire  [2:0] face_q$18$q;
    reg  face_q$18$clock;
    reg  [2:0] face_q$19$d;
    wire  [2:0] face_q$19$q;
    reg  face_q$19$clock;
    reg  [2:0] face_q$20$d;
    wire  [2:0] face_q$20$q;
    reg  face_q$20$clock;
    
    // Local signals
    reg  x_out;
    reg  y_out;
    reg  dx_nz;
    reg  dy_nz;
    reg  [6:0] sel;
    
    // Sub module instances
    top$lanes$0$ctl$nx_last nx_last(
        .d(nx_last$d),
        .q(nx_last$q),
        .clock(nx_last$clock)
    );
    top$lanes$0$ctl$ny_last ny_last(
        .d(ny_last$d),
        .q(ny_last$q),
        .clock(ny_last$clock)
    );
    top$lanes$0$ctl$sel_q$0 sel_q$0(
        .d(sel_q$0$d),
        .q(sel_q$0$q),
        .clock(sel_q$0$clock)
    );
    top$lanes$0$ctl$sel_q$1 sel_q$1(
        .d(sel_q$1$d),
        .q(sel_q$1$q),
        .clock(sel_q$1$clock)
    );
    top$lanes$0$ctl$sel_q$2 sel_q$2(
        .d(sel_q$2$d),
        .q(sel_q$2$q),
        .clock(sel_q$2$clock)
    );
    top$lanes$0$ctl$sel_q$3 sel_q$3(
        .d(sel_q$3$d),
        .q(sel_q$3$q),
        .clock(sel_q$3$clock)
    );
    top$lanes$0$ctl$x_q$0 x_q$0(
        .d(x_q$0$d),
        .q(x_q$0$q),
        .clock(x_q$0$clock)
    );
    top$lanes$0$ctl$x_q$1 x_q$1(
        .d(x_q$1$d),
        .q(x_q$1$q),
        .clock(x_q$1$clock)
    );
    top$lanes$0$ctl$x_q$2 x_q$2(
        .d(x_q$2$d),
        .q(x_q$2$q),
        .clock(x_q$2$clock)
    );
    top$lanes$0$ctl$x_q$3 x_q$3(
        .d(x_q$3$d),
        .q(x_q$3$q),
        .clock(x_q$3$clock)
    );
    top$lanes$0$ctl$x_q$4 x_q$4(
        .d(x_q$4$d),
        .q(x_q$4$q),
        .clock(x_q$4$clock)
    );
    top$lanes$0$ctl$x_q$5 x_q$5(
        .d(x_q$5$d),
        .q(x_q$5$q),
        .clock(x_q$5$clock)
    );
    top$lanes$0$ctl$x_q$6 x_q$6(
        .d(x_q$6$d),
        .q(x_q$6$q),
        .clock(x_q$6$clock)
    );
    top$lanes$0$ctl$x_q$7 x_q$7(
        .d(x_q$7$d),
        .q(x_q$7$q),
        .clock(x_q$7$clock)
    );
    top$lanes$0$ctl$x_q$8 x_q$8(
        .d(x_q$8$d),
        .q(x_q$8$q),
        .clock(x_q$8$clock)
    );
    top$lanes$0$ctl$x_q$9 x_q$9(
        .d(x_q$9$d),
        .q(x_q$9$q),
        .clock(x_q$9$clock)
    );
    top$lanes$0$ctl$y_q$0 y_q$0(
        .d(y_q$0$d),
        .q(y_q$0$q),
        .clock(y_q$0$clock)
    );
    top$lanes$0$ctl$y_q$1 y_q$1(
        .d(y_q$1$d),
        .q(y_q$1$q),
        .clock(y_q$1$clock)
    );
    top$lanes$0$ctl$y_q$2 y_q$2(
        .d(y_q$2$d),
        .q(y_q$2$q),
        .clock(y_q$2$clock)
    );
    top$lanes$0$ctl$y_q$3 y_q$3(
        .d(y_q$3$d),
        .q(y_q$3$q),
        .clock(y_q$3$clock)
    );
    top$lanes$0$ctl$y_q$4 y_q$4(
        .d(y_q$4$d),
        .q(y_q$4$q),
        .clock(y_q$4$clock)
    );
    top$lanes$0$ctl$y_q$5 y_q$5(
        .d(y_q$5$d),
        .q(y_q$5$q),
        .clock(y_q$5$clock)
    );
    top$lanes$0$ctl$y_q$6 y_q$6(
        .d(y_q$6$d),
        .q(y_q$6$q),
        .clock(y_q$6$clock)
    );
    top$lanes$0$ctl$y_q$7 y_q$7(
        .d(y_q$7$d),
        .q(y_q$7$q),
        .clock(y_q$7$clock)
    );
    top$lanes$0$ctl$y_q$8 y_q$8(
        .d(y_q$8$d),
        .q(y_q$8$q),
        .clock(y_q$8$clock)
    );
    top$lanes$0$ctl$sr_q$0 sr_q$0(
        .d(sr_q$0$d),
        .q(sr_q$0$q),
        .clock(sr_q$0$clock)
    );
    top$lanes$0$ctl$sr_q$1 sr_q$1(
        .d(sr_q$1$d),
        .q(sr_q$1$q),
        .clock(sr_q$1$clock)
    );
    top$lanes$0$ctl$sr_q$2 sr_q$2(
        .d(sr_q$2$d),
        .q(sr_q$2$q),
        .clock(sr_q$2$clock)
    );
    top$lanes$0$ctl$sr_q$3 sr_q$3(
        .d(sr_q$3$d),
        .q(sr_q$3$q),
        .clock(sr_q$3$clock)
    );
    top$lanes$0$ctl$sr_q$4 sr_q$4(
        .d(sr_q$4$d),
        .q(sr_q$4$q),
        .clock(sr_q$4$clock)
    );
    top$lanes$0$ctl$sr_q$5 sr_q$5(
        .d(sr_q$5$d),
        .q(sr_q$5$q),
        .clock(sr_q$5$clock)
    );
    top$lanes$0$ctl$sr_q$6 sr_q$6(
        .d(sr_q$6$d),
        .q(sr_q$6$q),
        .clock(sr_q$6$clock)
    );
    top$lanes$0$ctl$sr_q$7 sr_q$7(
        .d(sr_q$7$d),
        .q(sr_q$7$q),
        .clock(sr_q$7$clock)
    );
    top$lanes$0$ctl$sr_q$8 sr_q$8(
        .d(sr_q$8$d),
        .q(sr_q$8$q),
        .clock(sr_q$8$clock)
    );
    top$lanes$0$ctl$dxn_q$0 dxn_q$0(
        .d(dxn_q$0$d),
        .q(dxn_q$0$q),
        .clock(dxn_q$0$clock)
    );
    top$lanes$0$ctl$dxn_q$1 dxn_q$1(
        .d(dxn_q$1$d),
        .q(dxn_q$1$q),
        .clock(dxn_q$1$clock)
    );
    top$lanes$0$ctl$dxn_q$2 dxn_q$2(
        .d(dxn_q$2$d),
        .q(dxn_q$2$q),
        .clock(dxn_q$2$clock)
    );
    top$lanes$0$ctl$dxn_q$3 dxn_q$3(
        .d(dxn_q$3$d),
        .q(dxn_q$3$q),
        .clock(dxn_q$3$clock)
    );
    top$lanes$0$ctl$dxn_q$4 dxn_q$4(
        .d(dxn_q$4$d),
        .q(dxn_q$4$q),
        .clock(dxn_q$4$clock)
    );
    top$lanes$0$ctl$dxn_q$5 dxn_q$5(
        .d(dxn_q$5$d),
        .q(dxn_q$5$q),
        .clock(dxn_q$5$clock)
    );
    top$lanes$0$ctl$dxn_q$6 dxn_q$6(
        .d(dxn_q$6$d),
        .q(dxn_q$6$q),
        .clock(dxn_q$6$clock)
    );
    top$lanes$0$ctl$dxn_q$7 dxn_q$7(
        .d(dxn_q$7$d),
        .q(dxn_q$7$q),
        .clock(dxn_q$7$clock)
    );
    top$lanes$0$ctl$dxn_q$8 dxn_q$8(
        .d(dxn_q$8$d),
        .q(dxn_q$8$q),
        .clock(dxn_q$8$clock)
    );
    top$lanes$0$ctl$dxm_q$0 dxm_q$0(
        .d(dxm_q$0$d),
        .q(dxm_q$0$q),
        .clock(dxm_q$0$clock)
    );
    top$lanes$0$ctl$dxm_q$1 dxm_q$1(
        .d(dxm_q$1$d),
        .q(dxm_q$1$q),
        .clock(dxm_q$1$clock)
    );
    top$lanes$0$ctl$dxm_q$2 dxm_q$2(
        .d(dxm_q$2$d),
        .q(dxm_q$2$q),
        .clock(dxm_q$2$clock)
    );
    top$lanes$0$ctl$dxm_q$3 dxm_q$3(
        .d(dxm_q$3$d),
        .q(dxm_q$3$q),
        .clock(dxm_q$3$clock)
    );
    top$lanes$0$ctl$dxm_q$4 dxm_q$4(
        .d(dxm_q$4$d),
        .q(dxm_q$4$q),
        .clock(dxm_q$4$clock)
    );
    top$lanes$0$ctl$dxm_q$5 dxm_q$5(
        .d(dxm_q$5$d),
        .q(dxm_q$5$q),
        .clock(dxm_q$5$clock)
    );
    top$lanes$0$ctl$dxm_q$6 dxm_q$6(
        .d(dxm_q$6$d),
        .q(dxm_q$6$q),
        .clock(dxm_q$6$clock)
    );
    top$lanes$0$ctl$dxm_q$7 dxm_q$7(
        .d(dxm_q$7$d),
        .q(dxm_q$7$q),
        .clock(dxm_q$7$clock)
    );
    top$lanes$0$ctl$dxm_q$8 dxm_q$8(
        .d(dxm_q$8$d),
        .q(dxm_q$8$q),
        .clock(dxm_q$8$clock)
    );
    top$lanes$0$ctl$dxm_q$9 dxm_q$9(
        .d(dxm_q$9$d),
        .q(dxm_q$9$q),
        .clock(dxm_q$9$clock)
    );
    top$lanes$0$ctl$dyn_q$0 dyn_q$0(
        .d(dyn_q$0$d),
        .q(dyn_q$0$q),
        .clock(dyn_q$0$clock)
    );
    top$lanes$0$ctl$dyn_q$1 dyn_q$1(
        .d(dyn_q$1$d),
        .q(dyn_q$1$q),
        .clock(dyn_q$1$clock)
    );
    top$lanes$0$ctl$dyn_q$2 dyn_q$2(
        .d(dyn_q$2$d),
        .q(dyn_q$2$q),
        .clock(dyn_q$2$clock)
    );
    top$lanes$0$ctl$dyn_q$3 dyn_q$3(
        .d(dyn_q$3$d),
        .q(dyn_q$3$q),
        .clock(dyn_q$3$clock)
    );
    top$lanes$0$ctl$dyn_q$4 dyn_q$4(
        .d(dyn_q$4$d),
        .q(dyn_q$4$q),
        .clock(dyn_q$4$clock)
    );
    top$lanes$0$ctl$dyn_q$5 dyn_q$5(
        .d(dyn_q$5$d),
        .q(dyn_q$5$q),
        .clock(dyn_q$5$clock)
    );
    top$lanes$0$ctl$dyn_q$6 dyn_q$6(
        .d(dyn_q$6$d),
        .q(dyn_q$6$q),
        .clock(dyn_q$6$clock)
    );
    top$lanes$0$ctl$dyn_q$7 dyn_q$7(
        .d(dyn_q$7$d),
        .q(dyn_q$7$q),
        .clock(dyn_q$7$clock)
    );
    top$lanes$0$ctl$dyn_q$8 dyn_q$8(
        .d(dyn_q$8$d),
        .q(dyn_q$8$q),
        .clock(dyn_q$8$clock)
    );
    top$lanes$0$ctl$dym_q$0 dym_q$0(
        .d(dym_q$0$d),
        .q(dym_q$0$q),
        .clock(dym_q$0$clock)
    );
    top$lanes$0$ctl$dym_q$1 dym_q$1(
        .d(dym_q$1$d),
        .q(dym_q$1$q),
        .clock(dym_q$1$clock)
    );
    top$lanes$0$ctl$dym_q$2 dym_q$2(
        .d(dym_q$2$d),
        .q(dym_q$2$q),
        .clock(dym_q$2$clock)
    );
    top$lanes$0$ctl$dym_q$3 dym_q$3(
        .d(dym_q$3$d),
        .q(dym_q$3$q),
        .clock(dym_q$3$clock)
    );
    top$lanes$0$ctl$dym_q$4 dym_q$4(
        .d(dym_q$4$d),
        .q(dym_q$4$q),
        .clock(dym_q$4$clock)
    );
    top$lanes$0$ctl$dym_q$5 dym_q$5(
        .d(dym_q$5$d),
        .q(dym_q$5$q),
        .clock(dym_q$5$clock)
    );
    top$lanes$0$ctl$dym_q$6 dym_q$6(
        .d(dym_q$6$d),
        .q(dym_q$6$q),
        .clock(dym_q$6$clock)
    );
    top$lanes$0$ctl$dym_q$7 dym_q$7(
        .d(dym_q$7$d),
        .q(dym_q$7$q),
        .clock(dym_q$7$clock)
    );
    top$lanes$0$ctl$dym_q$8 dym_q$8(
        .d(dym_q$8$d),
        .q(dym_q$8$q),
        .clock(dym_q$8$clock)
    );
    top$lanes$0$ctl$dym_q$9 dym_q$9(
        .d(dym_q$9$d),
        .q(dym_q$9$q),
        .clock(dym_q$9$clock)
    );
    top$lanes$0$ctl$v_q$0 v_q$0(
        .d(v_q$0$d),
        .q(v_q$0$q),
        .clock(v_q$0$clock)
    );
    top$lanes$0$ctl$v_q$1 v_q$1(
        .d(v_q$1$d),
        .q(v_q$1$q),
        .clock(v_q$1$clock)
    );
    top$lanes$0$ctl$v_q$2 v_q$2(
        .d(v_q$2$d),
        .q(v_q$2$q),
        .clock(v_q$2$clock)
    );
    top$lanes$0$ctl$v_q$3 v_q$3(
        .d(v_q$3$d),
        .q(v_q$3$q),
        .clock(v_q$3$clock)
    );
    top$lanes$0$ctl$v_q$4 v_q$4(
        .d(v_q$4$d),
        .q(v_q$4$q),
        .clock(v_q$4$clock)
    );
    top$lanes$0$ctl$v_q$5 v_q$5(
        .d(v_q$5$d),
        .q(v_q$5$q),
        .clock(v_q$5$clock)
    );
    top$lanes$0$ctl$v_q$6 v_q$6(
        .d(v_q$6$d),
        .q(v_q$6$q),
        .clock(v_q$6$clock)
    );
    top$lanes$0$ctl$v_q$7 v_q$7(
        .d(v_q$7$d),
        .q(v_q$7$q),
        .clock(v_q$7$clock)
    );
    top$lanes$0$ctl$v_q$8 v_q$8(
        .d(v_q$8$d),
        .q(v_q$8$q),
        .clock(v_q$8$clock)
    );
    top$lanes$0$ctl$v_q$9 v_q$9(
        .d(v_q$9$d),
        .q(v_q$9$q),
        .clock(v_q$9$clock)
    );
    top$lanes$0$ctl$v_q$10 v_q$10(
        .d(v_q$10$d),
        .q(v_q$10$q),
        .clock(v_q$10$clock)
    );
    top$lanes$0$ctl$v_q$11 v_q$11(
        .d(v_q$11$d),
        .q(v_q$11$q),
        .clock(v_q$11$clock)
    );
    top$lanes$0$ctl$v_q$12 v_q$12(
        .d(v_q$12$d),
        .q(v_q$12$q),
        .clock(v_q$12$clock)
    );
    top$lanes$0$ctl$v_q$13 v_q$13(
        .d(v_q$13$d),
        .q(v_q$13$q),
        .clock(v_q$13$clock)
    );
    top$lanes$0$ctl$v_q$14 v_q$14(
        .d(v_q$14$d),
        .q(v_q$14$q),
        .clock(v_q$14$clock)
    );
    top$lanes$0$ctl$v_q$15 v_q$15(
        .d(v_q$15$d),
        .q(v_q$15$q),
        .clock(v_q$15$clock)
    );
    top$lanes$0$ctl$v_q$16 v_q$16(
        .d(v_q$16$d),
        .q(v_q$16$q),
        .clock(v_q$16$clock)
    );
    top$lanes$0$ctl$v_q$17 v_q$17(
        .d(v_q$17$d),
        .q(v_q$17$q),
        .clock(v_q$17$clock)
    );
    top$lanes$0$ctl$v_q$18 v_q$18(
        .d(v_q$18$d),
        .q(v_q$18$q),
        .clock(v_q$18$clock)
    );
    top$lanes$0$ctl$v_q$19 v_q$19(
        .d(v_q$19$d),
        .q(v_q$19$q),
        .clock(v_q$19$clock)
    );
    top$lanes$0$ctl$v_q$20 v_q$20(
        .d(v_q$20$d),
        .q(v_q$20$q),
        .clock(v_q$20$clock)
    );
    top$lanes$0$ctl$er_q$0 er_q$0(
        .d(er_q$0$d),
        .q(er_q$0$q),
        .clock(er_q$0$clock)
    );
    top$lanes$0$ctl$er_q$1 er_q$1(
        .d(er_q$1$d),
        .q(er_q$1$q),
        .clock(er_q$1$clock)
    );
    top$lanes$0$ctl$er_q$2 er_q$2(
        .d(er_q$2$d),
        .q(er_q$2$q),
        .clock(er_q$2$clock)
    );
    top$lanes$0$ctl$er_q$3 er_q$3(
        .d(er_q$3$d),
        .q(er_q$3$q),
        .clock(er_q$3$clock)
    );
    top$lanes$0$ctl$er_q$4 er_q$4(
        .d(er_q$4$d),
        .q(er_q$4$q),
        .clock(er_q$4$clock)
    );
    top$lanes$0$ctl$er_q$5 er_q$5(
        .d(er_q$5$d),
        .q(er_q$5$q),
        .clock(er_q$5$clock)
    );
    top$lanes$0$ctl$er_q$6 er_q$6(
        .d(er_q$6$d),
        .q(er_q$6$q),
        .clock(er_q$6$clock)
    );
    top$lanes$0$ctl$er_q$7 er_q$7(
        .d(er_q$7$d),
        .q(er_q$7$q),
        .clock(er_q$7$clock)
    );
    top$lanes$0$ctl$er_q$8 er_q$8(
        .d(er_q$8$d),
        .q(er_q$8$q),
        .clock(er_q$8$clock)
    );
    top$lanes$0$ctl$er_q$9 er_q$9(
        .d(er_q$9$d),
        .q(er_q$9$q),
        .clock(er_q$9$clock)
    );
    top$lanes$0$ctl$er_q$10 er_q$10(
        .d(er_q$10$d),
        .q(er_q$10$q),
        .clock(er_q$10$clock)
    );
    top$lanes$0$ctl$er_q$11 er_q$11(
        .d(er_q$11$d),
        .q(er_q$11$q),
        .clock(er_q$11$clock)
    );
    top$lanes$0$ctl$er_q$12 er_q$12(
        .d(er_q$12$d),
        .q(er_q$12$q),
        .clock(er_q$12$clock)
    );
    top$lanes$0$ctl$er_q$13 er_q$13(
        .d(er_q$13$d),
        .q(er_q$13$q),
        .clock(er_q$13$clock)
    );
    top$lanes$0$ctl$er_q$14 er_q$14(
        .d(er_q$14$d),
        .q(er_q$14$q),
        .clock(er_q$14$clock)
    );
    top$lanes$0$ctl$er_q$15 er_q$15(
        .d(er_q$15$d),
        .q(er_q$15$q),
        .clock(er_q$15$clock)
    );
    top$lanes$0$ctl$er_q$16 er_q$16(
        .d(er_q$16$d),
        .q(er_q$16$q),
        .clock(er_q$16$clock)
    );
    top$lanes$0$ctl$er_q$17 er_q$17(
        .d(er_q$17$d),
        .q(er_q$17$q),
        .clock(er_q$17$clock)
    );
    top$lanes$0$ctl$er_q$18 er_q$18(
        .d(er_q$18$d),
        .q(er_q$18$q),
        .clock(er_q$18$clock)
    );
    top$lanes$0$ctl$er_q$19 er_q$19(
        .d(er_q$19$d),
        .q(er_q$19$q),
        .clock(er_q$19$clock)
    );
    top$lanes$0$ctl$er_q$20 er_q$20(
        .d(er_q$20$d),
        .q(er_q$20$q),
        .clock(er_q$20$clock)
    );
    top$lanes$0$ctl$pad_q$0 pad_q$0(
        .d(pad_q$0$d),
        .q(pad_q$0$q),
        .clock(pad_q$0$clock)
    );
    top$lanes$0$ctl$pad_q$1 pad_q$1(
        .d(pad_q$1$d),
        .q(pad_q$1$q),
        .clock(pad_q$1$clock)
    );
    top$lanes$0$ctl$pad_q$2 pad_q$2(
        .d(pad_q$2$d),
        .q(pad_q$2$q),
        .clock(pad_q$2$clock)
    );
    top$lanes$0$ctl$pad_q$3 pad_q$3(
        .d(pad_q$3$d),
        .q(pad_q$3$q),
        .clock(pad_q$3$clock)
    );
    top$lanes$0$ctl$pad_q$4 pad_q$4(
        .d(pad_q$4$d),
        .q(pad_q$4$q),
        .clock(pad_q$4$clock)
    );
    top$lanes$0$ctl$pad_q$5 pad_q$5(
        .d(pad_q$5$d),
        .q(pad_q$5$q),
        .clock(pad_q$5$clock)
    );
    top$lanes$0$ctl$pad_q$6 pad_q$6(
        .d(pad_q$6$d),
        .q(pad_q$6$q),
        .clock(pad_q$6$clock)
    );
    top$lanes$0$ctl$pad_q$7 pad_q$7(
        .d(pad_q$7$d),
        .q(pad_q$7$q),
        .clock(pad_q$7$clock)
    );
    top$lanes$0$ctl$pad_q$8 pad_q$8(
        .d(pad_q$8$d),
        .q(pad_q$8$q),
        .clock(pad_q$8$clock)
    );
    top$lanes$0$ctl$pad_q$9 pad_q$9(
        .d(pad_q$9$d),
        .q(pad_q$9$q),
        .clock(pad_q$9$clock)
    );
    top$lanes$0$ctl$pad_q$10 pad_q$10(
        .d(pad_q$10$d),
        .q(pad_q$10$q),
        .clock(pad_q$10$clock)
    );
    top$lanes$0$ctl$pad_q$11 pad_q$11(
        .d(pad_q$11$d),
        .q(pad_q$11$q),
        .clock(pad_q$11$clock)
    );
    top$lanes$0$ctl$pad_q$12 pad_q$12(
        .d(pad_q$12$d),
        .q(pad_q$12$q),
        .clock(pad_q$12$clock)
    );
    top$lanes$0$ctl$pad_q$13 pad_q$13(
        .d(pad_q$13$d),
        .q(pad_q$13$q),
        .clock(pad_q$13$clock)
    );
    top$lanes$0$ctl$pad_q$14 pad_q$14(
        .d(pad_q$14$d),
        .q(pad_q$14$q),
        .clock(pad_q$14$clock)
    );
    top$lanes$0$ctl$pad_q$15 pad_q$15(
        .d(pad_q$15$d),
        .q(pad_q$15$q),
        .clock(pad_q$15$clock)
    );
    top$lanes$0$ctl$pad_q$16 pad_q$16(
        .d(pad_q$16$d),
        .q(pad_q$16$q),
        .clock(pad_q$16$clock)
    );
    top$lanes$0$ctl$pad_q$17 pad_q$17(
        .d(pad_q$17$d),
        .q(pad_q$17$q),
        .clock(pad_q$17$clock)
    );
    top$lanes$0$ctl$pad_q$18 pad_q$18(
        .d(pad_q$18$d),
        .q(pad_q$18$q),
        .clock(pad_q$18$clock)
    );
    top$lanes$0$ctl$pad_q$19 pad_q$19(
        .d(pad_q$19$d),
        .q(pad_q$19$q),
        .clock(pad_q$19$clock)
    );
    top$lanes$0$ctl$pad_q$20 pad_q$20(
        .d(pad_q$20$d),
        .q(pad_q$20$q),
        .clock(pad_q$20$clock)
    );
    top$lanes$0$ctl$bx_q$0 bx_q$0(
        .d(bx_q$0$d),
        .q(bx_q$0$q),
        .clock(bx_q$0$clock)
    );
    top$lanes$0$ctl$bx_q$1 bx_q$1(
        .d(bx_q$1$d),
        .q(bx_q$1$q),
        .clock(bx_q$1$clock)
    );
    top$lanes$0$ctl$bx_q$2 bx_q$2(
        .d(bx_q$2$d),
        .q(bx_q$2$q),
        .clock(bx_q$2$clock)
    );
    top$lanes$0$ctl$bx_q$3 bx_q$3(
        .d(bx_q$3$d),
        .q(bx_q$3$q),
        .clock(bx_q$3$clock)
    );
    top$lanes$0$ctl$bx_q$4 bx_q$4(
        .d(bx_q$4$d),
        .q(bx_q$4$q),
        .clock(bx_q$4$clock)
    );
    top$lanes$0$ctl$bx_q$5 bx_q$5(
        .d(bx_q$5$d),
        .q(bx_q$5$q),
        .clock(bx_q$5$clock)
    );
    top$lanes$0$ctl$bx_q$6 bx_q$6(
        .d(bx_q$6$d),
        .q(bx_q$6$q),
        .clock(bx_q$6$clock)
    );
    top$lanes$0$ctl$bx_q$7 bx_q$7(
        .d(bx_q$7$d),
        .q(bx_q$7$q),
        .clock(bx_q$7$clock)
    );
    top$lanes$0$ctl$bx_q$8 bx_q$8(
        .d(bx_q$8$d),
        .q(bx_q$8$q),
        .clock(bx_q$8$clock)
    );
    top$lanes$0$ctl$bx_q$9 bx_q$9(
        .d(bx_q$9$d),
        .q(bx_q$9$q),
        .clock(bx_q$9$clock)
    );
    top$lanes$0$ctl$bx_q$10 bx_q$10(
        .d(bx_q$10$d),
        .q(bx_q$10$q),
        .clock(bx_q$10$clock)
    );
    top$lanes$0$ctl$bx_q$11 bx_q$11(
        .d(bx_q$11$d),
        .q(bx_q$11$q),
        .clock(bx_q$11$clock)
    );
    top$lanes$0$ctl$bx_q$12 bx_q$12(
        .d(bx_q$12$d),
        .q(bx_q$12$q),
        .clock(bx_q$12$clock)
    );
    top$lanes$0$ctl$bx_q$13 bx_q$13(
        .d(bx_q$13$d),
        .q(bx_q$13$q),
        .clock(bx_q$13$clock)
    );
    top$lanes$0$ctl$bx_q$14 bx_q$14(
        .d(bx_q$14$d),
        .q(bx_q$14$q),
        .clock(bx_q$14$clock)
    );
    top$lanes$0$ctl$bx_q$15 bx_q$15(
        .d(bx_q$15$d),
        .q(bx_q$15$q),
        .clock(bx_q$15$clock)
    );
    top$lanes$0$ctl$bx_q$16 bx_q$16(
        .d(bx_q$16$d),
        .q(bx_q$16$q),
        .clock(bx_q$16$clock)
    );
    top$lanes$0$ctl$bx_q$17 bx_q$17(
        .d(bx_q$17$d),
        .q(bx_q$17$q),
        .clock(bx_q$17$clock)
    );
    top$lanes$0$ctl$bx_q$18 bx_q$18(
        .d(bx_q$18$d),
        .q(bx_q$18$q),
        .clock(bx_q$18$clock)
    );
    top$lanes$0$ctl$bx_q$19 bx_q$19(
        .d(bx_q$19$d),
        .q(bx_q$19$q),
        .clock(bx_q$19$clock)
    );
    top$lanes$0$ctl$bx_q$20 bx_q$20(
        .d(bx_q$20$d),
        .q(bx_q$20$q),
        .clock(bx_q$20$clock)
    );
    top$lanes$0$ctl$by_q$0 by_q$0(
        .d(by_q$0$d),
        .q(by_q$0$q),
        .clock(by_q$0$clock)
    );
    top$lanes$0$ctl$by_q$1 by_q$1(
        .d(by_q$1$d),
        .q(by_q$1$q),
        .clock(by_q$1$clock)
    );
    top$lanes$0$ctl$by_q$2 by_q$2(
        .d(by_q$2$d),
        .q(by_q$2$q),
        .clock(by_q$2$clock)
    );
    top$lanes$0$ctl$by_q$3 by_q$3(
        .d(by_q$3$d),
        .q(by_q$3$q),
        .clock(by_q$3$clock)
    );
    top$lanes$0$ctl$by_q$4 by_q$4(
        .d(by_q$4$d),
        .q(by_q$4$q),
        .clock(by_q$4$clock)
    );
    top$lanes$0$ctl$by_q$5 by_q$5(
        .d(by_q$5$d),
        .q(by_q$5$q),
        .clock(by_q$5$clock)
    );
    top$lanes$0$ctl$by_q$6 by_q$6(
        .d(by_q$6$d),
        .q(by_q$6$q),
        .clock(by_q$6$clock)
    );
    top$lanes$0$ctl$by_q$7 by_q$7(
        .d(by_q$7$d),
        .q(by_q$7$q),
        .clock(by_q$7$clock)
    );
    top$lanes$0$ctl$by_q$8 by_q$8(
        .d(by_q$8$d),
        .q(by_q$8$q),
        .clock(by_q$8$clock)
    );
    top$lanes$0$ctl$by_q$9 by_q$9(
        .d(by_q$9$d),
        .q(by_q$9$q),
        .clock(by_q$9$clock)
    );
    top$lanes$0$ctl$by_q$10 by_q$10(
        .d(by_q$10$d),
        .q(by_q$10$q),
        .clock(by_q$10$clock)
    );
    top$lanes$0$ctl$by_q$11 by_q$11(
        .d(by_q$11$d),
        .q(by_q$11$q),
        .clock(by_q$11$clock)
    );
    top$lanes$0$ctl$by_q$12 by_q$12(
        .d(by_q$12$d),
        .q(by_q$12$q),
        .clock(by_q$12$clock)
    );
    top$lanes$0$ctl$by_q$13 by_q$13(
        .d(by_q$13$d),
        .q(by_q$13$q),
        .clock(by_q$13$clock)
    );
    top$lanes$0$ctl$by_q$14 by_q$14(
        .d(by_q$14$d),
        .q(by_q$14$q),
        .clock(by_q$14$clock)
    );
    top$lanes$0$ctl$by_q$15 by_q$15(
        .d(by_q$15$d),
        .q(by_q$15$q),
        .clock(by_q$15$clock)
    );
    top$lanes$0$ctl$by_q$16 by_q$16(
        .d(by_q$16$d),
        .q(by_q$16$q),
        .clock(by_q$16$clock)
    );
    top$lanes$0$ctl$by_q$17 by_q$17(
        .d(by_q$17$d),
        .q(by_q$17$q),
        .clock(by_q$17$clock)
    );
    top$lanes$0$ctl$by_q$18 by_q$18(
        .d(by_q$18$d),
        .q(by_q$18$q),
        .clock(by_q$18$clock)
    );
    top$lanes$0$ctl$by_q$19 by_q$19(
        .d(by_q$19$d),
        .q(by_q$19$q),
        .clock(by_q$19$clock)
    );
    top$lanes$0$ctl$by_q$20 by_q$20(
        .d(by_q$20$d),
        .q(by_q$20$q),
        .clock(by_q$20$clock)
    );
    top$lanes$0$ctl$face_q$0 face_q$0(
        .d(face_q$0$d),
        .q(face_q$0$q),
        .clock(face_q$0$clock)
    );
    top$lanes$0$ctl$face_q$1 face_q$1(
        .d(face_q$1$d),
        .q(face_q$1$q),
        .clock(face_q$1$clock)
    );
    top$lanes$0$ctl$face_q$2 face_q$2(
        .d(face_q$2$d),
        .q(face_q$2$q),
        .clock(face_q$2$clock)
    );
    top$lanes$0$ctl$face_q$3 face_q$3(
        .d(face_q$3$d),
        .q(face_q$3$q),
        .clock(face_q$3$clock)
    );
    top$lanes$0$ctl$face_q$4 face_q$4(
        .d(face_q$4$d),
        .q(face_q$4$q),
        .clock(face_q$4$clock)
    );
    top$lanes$0$ctl$face_q$5 face_q$5(
        .d(face_q$5$d),
        .q(face_q$5$q),
        .clock(face_q$5$clock)
    );
    top$lanes$0$ctl$face_q$6 face_q$6(
        .d(face_q$6$d),
        .q(face_q$6$q),
        .clock(face_q$6$clock)
    );
    top$lanes$0$ctl$face_q$7 face_q$7(
        .d(face_q$7$d),
        .q(face_q$7$q),
        .clock(face_q$7$clock)
    );
    top$lanes$0$ctl$face_q$8 face_q$8(
        .d(face_q$8$d),
        .q(face_q$8$q),
        .clock(face_q$8$clock)
    );
    top$lanes$0$ctl$face_q$9 face_q$9(
        .d(face_q$9$d),
        .q(face_q$9$q),
        .clock(face_q$9$clock)
    );
    top$lanes$0$ctl$face_q$10 face_q$10(
        .d(face_q$10$d),
        .q(face_q$10$q),
        .clock(face_q$10$clock)
    );
    top$lanes$0$ctl$face_q$11 face_q$11(
        .d(face_q$11$d),
        .q(face_q$11$q),
        .clock(face_q$11$clock)
    );
    top$lanes$0$ctl$face_q$12 face_q$12(
        .d(face_q$12$d),
        .q(face_q$12$q),
        .clock(face_q$12$clock)
    );
    top$lanes$0$ctl$face_q$13 face_q$13(
        .d(face_q$13$d),
        .q(face_q$13$q),
        .clock(face_q$13$clock)
    );
    top$lanes$0$ctl$face_q$14 face_q$14(
        .d(face_q$14$d),
        .q(face_q$14$q),
        .clock(face_q$14$clock)
    );
    top$lanes$0$ctl$face_q$15 face_q$15(
        .d(face_q$15$d),
        .q(face_q$15$q),
        .clock(face_q$15$clock)
    );
    top$lanes$0$ctl$face_q$16 face_q$16(
        .d(face_q$16$d),
        .q(face_q$16$q),
        .clock(face_q$16$clock)
    );
    top$lanes$0$ctl$face_q$17 face_q$17(
        .d(face_q$17$d),
        .q(face_q$17$q),
        .clock(face_q$17$clock)
    );
    top$lanes$0$ctl$face_q$18 face_q$18(
        .d(face_q$18$d),
        .q(face_q$18$q),
        .clock(face_q$18$clock)
    );
    top$lanes$0$ctl$face_q$19 face_q$19(
        .d(face_q$19$d),
        .q(face_q$19$q),
        .clock(face_q$19$clock)
    );
    top$lanes$0$ctl$face_q$20 face_q$20(
        .d(face_q$20$d),
        .q(face_q$20$q),
        .clock(face_q$20$clock)
    );
    
    // Update code
    always @(*) begin
        nx_last$clock = clock;
        ny_last$clock = clock;
        nx_last$d = nx_last$q;
        ny_last$d = ny_last$q;
        x_q$0$clock = clock;
        dxm_q$0$clock = clock;
        dym_q$0$clock = clock;
        x_q$1$clock = clock;
        dxm_q$1$clock = clock;
        dym_q$1$clock = clock;
        x_q$2$clock = clock;
        dxm_q$2$clock = clock;
        dym_q$2$clock = clock;
        x_q$3$clock = clock;
        dxm_q$3$clock = clock;
        dym_q$3$clock = clock;
        x_q$4$clock = clock;
        dxm_q$4$clock = clock;
        dym_q$4$clock = clock;
        x_q$5$clock = clock;
        dxm_q$5$clock = clock;
        dym_q$5$clock = clock;
        x_q$6$clock = clock;
        dxm_q$6$clock = clock;
        dym_q$6$clock = clock;
        x_q$7$clock = clock;
        dxm_q$7$clock = clock;
        dym_q$7$clock = clock;
        x_q$8$clock = clock;
        dxm_q$8$clock = clock;
        dym_q$8$clock = clock;
        x_q$9$clock = clock;
        dxm_q$9$clock = clock;
        dym_q$9$clock = clock;
        v_q$0$clock = clock;
        er_q$0$clock = clock;
        pad_q$0$clock = clock;
        bx_q$0$clock = clock;
        by_q$0$clock = clock;
        face_q$0$clock = clock;
        v_q$1$clock = clock;
        er_q$1$clock = clock;
        pad_q$1$clock = clock;
        bx_q$1$clock = clock;
        by_q$1$clock = clock;
        face_q$1$clock = clock;
        v_q$2$clock = clock;
        er_q$2$clock = clock;
        pad_q$2$clock = clock;
        bx_q$2$clock = clock;
        by_q$2$clock = clock;
        face_q$2$clock = clock;
        v_q$3$clock = clock;
        er_q$3$clock = clock;
        pad_q$3$clock = clock;
        bx_q$3$clock = clock;
        by_q$3$clock = clock;
        face_q$3$clock = clock;
        v_q$4$clock = clock;
        er_q$4$clock = clock;
        pad_q$4$clock = clock;
        bx_q$4$clock = clock;
        by_q$4$clock = clock;
        face_q$4$clock = clock;
        v_q$5$clock = clock;
        er_q$5$clock = clock;
        pad_q$5$clock = clock;
        bx_q$5$clock = clock;
        by_q$5$clock = clock;
        face_q$5$clock = clock;
        v_q$6$clock = clock;
        er_q$6$clock = clock;
        pad_q$6$clock = clock;
        bx_q$6$clock = clock;
        by_q$6$clock = clock;
        face_q$6$clock = clock;
        v_q$7$clock = clock;
        er_q$7$clock = clock;
        pad_q$7$clock = clock;
        bx_q$7$clock = clock;
        by_q$7$clock = clock;
        face_q$7$clock = clock;
        v_q$8$clock = clock;
        er_q$8$clock = clock;
        pad_q$8$clock = clock;
        bx_q$8$clock = clock;
        by_q$8$clock = clock;
        face_q$8$clock = clock;
        v_q$9$clock = clock;
        er_q$9$clock = clock;
        pad_q$9$clock = clock;
        bx_q$9$clock = clock;
        by_q$9$clock = clock;
        face_q$9$clock = clock;
        v_q$10$clock = clock;
        er_q$10$clock = clock;
        pad_q$10$clock = clock;
        bx_q$10$clock = clock;
        by_q$10$clock = clock;
        face_q$10$clock = clock;
        v_q$11$clock = clock;
        er_q$11$clock = clock;
        pad_q$11$clock = clock;
        bx_q$11$clock = clock;
        by_q$11$clock = clock;
        face_q$11$clock = clock;
        v_q$12$clock = clock;
        er_q$12$clock = clock;
        pad_q$12$clock = clock;
        bx_q$12$clock = clock;
        by_q$12$clock = clock;
        face_q$12$clock = clock;
        v_q$13$clock = clock;
        er_q$13$clock = clock;
        pad_q$13$clock = clock;
        bx_q$13$clock = clock;
        by_q$13$clock = clock;
        face_q$13$clock = clock;
        v_q$14$clock = clock;
        er_q$14$clock = clock;
        pad_q$14$clock = clock;
        bx_q$14$clock = clock;
        by_q$14$clock = clock;
        face_q$14$clock = clock;
        v_q$15$clock = clock;
        er_q$15$clock = clock;
        pad_q$15$clock = clock;
        bx_q$15$clock = clock;
        by_q$15$clock = clock;
        face_q$15$clock = clock;
        v_q$16$clock = clock;
        er_q$16$clock = clock;
        pad_q$16$clock = clock;
        bx_q$16$clock = clock;
        by_q$16$clock = clock;
        face_q$16$clock = clock;
        v_q$17$clock = clock;
        er_q$17$clock = clock;
        pad_q$17$clock = clock;
        bx_q$17$clock = clock;
        by_q$17$clock = clock;
        face_q$17$clock = clock;
        v_q$18$clock = clock;
        er_q$18$clock = clock;
        pad_q$18$clock = clock;
        bx_q$18$clock = clock;
        by_q$18$clock = clock;
        face_q$18$clock = clock;
        v_q$19$clock = clock;
        er_q$19$clock = clock;
        pad_q$19$clock = clock;
        bx_q$19$clock = clock;
        by_q$19$clock = clock;
        face_q$19$clock = clock;
        v_q$20$clock = clock;
        er_q$20$clock = clock;
        pad_q$20$clock = clock;
        bx_q$20$clock = clock;
        by_q$20$clock = clock;
        face_q$20$clock = clock;
        x_q$0$d = x & coord_mask;
        y_q$0$d = y & coord_mask;
        sr_q$0$d = sr;
        dxn_q$0$d = dx_neg;
        dxm_q$0$d = dx_mag;
        dyn_q$0$d = dy_neg;
        dym_q$0$d = dy_mag;
        x_q$1$d = x_q$0$q;
        dxm_q$1$d = dxm_q$0$q;
        dym_q$1$d = dym_q$0$q;
        x_q$2$d = x_q$1$q;
        dxm_q$2$d = dxm_q$1$q;
        dym_q$2$d = dym_q$1$q;
        x_q$3$d = x_q$2$q;
        dxm_q$3$d = dxm_q$2$q;
        dym_q$3$d = dym_q$2$q;
        x_q$4$d = x_q$3$q;
        dxm_q$4$d = dxm_q$3$q;
        dym_q$4$d = dym_q$3$q;
        x_q$5$d = x_q$4$q;
        dxm_q$5$d = dxm_q$4$q;
        dym_q$5$d = dym_q$4$q;
        x_q$6$d = x_q$5$q;
        dxm_q$6$d = dxm_q$5$q;
        dym_q$6$d = dym_q$5$q;
        x_q$7$d = x_q$6$q;
        dxm_q$7$d = dxm_q$6$q;
        dym_q$7$d = dym_q$6$q;
        x_q$8$d = x_q$7$q;
        dxm_q$8$d = dxm_q$7$q;
        dym_q$8$d = dym_q$7$q;
        x_q$9$d = x_q$8$q;
        dxm_q$9$d = dxm_q$8$q;
        dym_q$9$d = dym_q$8$q;
        y_q$0$clock = clock;
        sr_q$0$clock = clock;
        dxn_q$0$clock = clock;
        dyn_q$0$clock = clock;
        y_q$1$clock = clock;
        sr_q$1$clock = clock;
        dxn_q$1$clock = clock;
        dyn_q$1$clock = clock;
        y_q$2$clock = clock;
        sr_q$2$clock = clock;
        dxn_q$2$clock = clock;
        dyn_q$2$clock = clock;
        y_q$3$clock = clock;
        sr_q$3$clock = clock;
        dxn_q$3$clock = clock;
        dyn_q$3$clock = clock;
        y_q$4$clock = clock;
        sr_q$4$clock = clock;
        dxn_q$4$clock = clock;
        dyn_q$4$clock = clock;
        y_q$5$clock = clock;
        sr_q$5$clock = clock;
        dxn_q$5$clock = clock;
        dyn_q$5$clock = clock;
        y_q$6$clock = clock;
        sr_q$6$clock = clock;
        dxn_q$6$clock = clock;
        dyn_q$6$clock = clock;
        y_q$7$clock = clock;
        sr_q$7$clock = clock;
        dxn_q$7$clock = clock;
        dyn_q$7$clock = clock;
        y_q$8$clock = clock;
        sr_q$8$clock = clock;
        dxn_q$8$clock = clock;
        dyn_q$8$clock = clock;
        y_q$1$d = y_q$0$q;
        sr_q$1$d = sr_q$0$q;
        dxn_q$1$d = dxn_q$0$q;
        dyn_q$1$d = dyn_q$0$q;
        y_q$2$d = y_q$1$q;
        sr_q$2$d = sr_q$1$q;
        dxn_q$2$d = dxn_q$1$q;
        dyn_q$2$d = dyn_q$1$q;
        y_q$3$d = y_q$2$q;
        sr_q$3$d = sr_q$2$q;
        dxn_q$3$d = dxn_q$2$q;
        dyn_q$3$d = dyn_q$2$q;
        y_q$4$d = y_q$3$q;
        sr_q$4$d = sr_q$3$q;
        dxn_q$4$d = dxn_q$3$q;
        dyn_q$4$d = dyn_q$3$q;
        y_q$5$d = y_q$4$q;
        sr_q$5$d = sr_q$4$q;
        dxn_q$5$d = dxn_q$4$q;
        dyn_q$5$d = dyn_q$4$q;
        y_q$6$d = y_q$5$q;
        sr_q$6$d = sr_q$5$q;
        dxn_q$6$d = dxn_q$5$q;
        dyn_q$6$d = dyn_q$5$q;
        y_q$7$d = y_q$6$q;
        sr_q$7$d = sr_q$6$q;
        dxn_q$7$d = dxn_q$6$q;
        dyn_q$7$d = dyn_q$6$q;
        y_q$8$d = y_q$7$q;
        sr_q$8$d = sr_q$7$q;
        dxn_q$8$d = dxn_q$7$q;
        dyn_q$8$d = dyn_q$7$q;
        x_t = x_q$9$q;
        dx_mag_t = dxm_q$9$q;
        dy_mag_t = dym_q$9$q;
        nx_last$d = dims[('h0)+:(16)] - 'h1;
        ny_last$d = dims[('h10)+:(16)] - 'h1;
        x_out = 1'b0;
        if (dxm_q$8$q != 'h0) begin
            if (dxn_q$8$q) begin
                x_out = x_q$8$q == nx_last$q;
            end
            else begin
                x_out = x_q$8$q == 'h0;
            end
        end
        y_out = 1'b0;
        if (dym_q$8$q != 'h0) begin
            if (dyn_q$8$q) begin
                y_out = y_q$8$q == ny_last$q;
            end
            else begin
                y_out = y_q$8$q == 'h0;
            end
        end
        dx_nz = dxm_q$8$q != 'h0;
        dy_nz = dym_q$8$q != 'h0;
        sel = 7'(sr_q$8$q) | (7'(dxn_q$8$q) << 'h1) | (7'(dx_nz) << 'h2) | (7'(dyn_q$8$q) << 'h3) | (7'(dy_nz) << 'h4) | (7'(x_out) << 'h5) | (7'(y_out) << 'h6);
        sel_q$0$clock = clock;
        sel_q$0$d = sel;
        sel_t$0 = sel_q$0$q;
        sel_q$1$clock = clock;
        sel_q$1$d = sel;
        sel_t$1 = sel_q$1$q;
        sel_q$2$clock = clock;
        sel_q$2$d = sel;
        sel_t$2 = sel_q$2$q;
        sel_q$3$clock = clock;
        sel_q$3$d = sel;
        sel_t$3 = sel_q$3$q;
        v_q$0$d = valid;
        er_q$0$d = er;
        pad_q$0$d = pad;
        bx_q$0$d = base_x & coord_mask;
        by_q$0$d = base_y & coord_mask;
        face_q$0$d = face;
        v_q$1$d = v_q$0$q;
        er_q$1$d = er_q$0$q;
        pad_q$1$d = pad_q$0$q;
        bx_q$1$d = bx_q$0$q;
        by_q$1$d = by_q$0$q;
        face_q$1$d = face_q$0$q;
        v_q$2$d = v_q$1$q;
        er_q$2$d = er_q$1$q;
        pad_q$2$d = pad_q$1$q;
        bx_q$2$d = bx_q$1$q;
        by_q$2$d = by_q$1$q;
        face_q$2$d = face_q$1$q;
        v_q$3$d = v_q$2$q;
        er_q$3$d = er_q$2$q;
        pad_q$3$d = pad_q$2$q;
        bx_q$3$d = bx_q$2$q;
        by_q$3$d = by_q$2$q;
        face_q$3$d = face_q$2$q;
        v_q$4$d = v_q$3$q;
        er_q$4$d = er_q$3$q;
        pad_q$4$d = pad_q$3$q;
        bx_q$4$d = bx_q$3$q;
        by_q$4$d = by_q$3$q;
        face_q$4$d = face_q$3$q;
        v_q$5$d = v_q$4$q;
        er_q$5$d = er_q$4$q;
        pad_q$5$d = pad_q$4$q;
        bx_q$5$d = bx_q$4$q;
        by_q$5$d = by_q$4$q;
        face_q$5$d = face_q$4$q;
        v_q$6$d = v_q$5$q;
        er_q$6$d = er_q$5$q;
        pad_q$6$d = pad_q$5$q;
        bx_q$6$d = bx_q$5$q;
        by_q$6$d = by_q$5$q;
        face_q$6$d = face_q$5$q;
        v_q$7$d = v_q$6$q;
        er_q$7$d = er_q$6$q;
        pad_q$7$d = pad_q$6$q;
        bx_q$7$d = bx_q$6$q;
        by_q$7$d = by_q$6$q;
        face_q$7$d = face_q$6$q;
        v_q$8$d = v_q$7$q;
        er_q$8$d = er_q$7$q;
        pad_q$8$d = pad_q$7$q;
        bx_q$8$d = bx_q$7$q;
        by_q$8$d = by_q$7$q;
        face_q$8$d = face_q$7$q;
        v_q$9$d = v_q$8$q;
        er_q$9$d = er_q$8$q;
        pad_q$9$d = pad_q$8$q;
        bx_q$9$d = bx_q$8$q;
        by_q$9$d = by_q$8$q;
        face_q$9$d = face_q$8$q;
        v_q$10$d = v_q$9$q;
        er_q$10$d = er_q$9$q;
        pad_q$10$d = pad_q$9$q;
        bx_q$10$d = bx_q$9$q;
        by_q$10$d = by_q$9$q;
        face_q$10$d = face_q$9$q;
        v_q$11$d = v_q$10$q;
        er_q$11$d = er_q$10$q;
        pad_q$11$d = pad_q$10$q;
        bx_q$11$d = bx_q$10$q;
        by_q$11$d = by_q$10$q;
        face_q$11$d = face_q$10$q;
        v_q$12$d = v_q$11$q;
        er_q$12$d = er_q$11$q;
        pad_q$12$d = pad_q$11$q;
        bx_q$12$d = bx_q$11$q;
        by_q$12$d = by_q$11$q;
        face_q$12$d = face_q$11$q;
        v_q$13$d = v_q$12$q;
        er_q$13$d = er_q$12$q;
        pad_q$13$d = pad_q$12$q;
        bx_q$13$d = bx_q$12$q;
        by_q$13$d = by_q$12$q;
        face_q$13$d = face_q$12$q;
        v_q$14$d = v_q$13$q;
        er_q$14$d = er_q$13$q;
        pad_q$14$d = pad_q$13$q;
        bx_q$14$d = bx_q$13$q;
        by_q$14$d = by_q$13$q;
        face_q$14$d = face_q$13$q;
        v_q$15$d = v_q$14$q;
        er_q$15$d = er_q$14$q;
        pad_q$15$d = pad_q$14$q;
        bx_q$15$d = bx_q$14$q;
        by_q$15$d = by_q$14$q;
        face_q$15$d = face_q$14$q;
        v_q$16$d = v_q$15$q;
        er_q$16$d = er_q$15$q;
        pad_q$16$d = pad_q$15$q;
        bx_q$16$d = bx_q$15$q;
        by_q$16$d = by_q$15$q;
        face_q$16$d = face_q$15$q;
        v_q$17$d = v_q$16$q;
        er_q$17$d = er_q$16$q;
        pad_q$17$d = pad_q$16$q;
        bx_q$17$d = bx_q$16$q;
        by_q$17$d = by_q$16$q;
        face_q$17$d = face_q$16$q;
        v_q$18$d = v_q$17$q;
        er_q$18$d = er_q$17$q;
        pad_q$18$d = pad_q$17$q;
        bx_q$18$d = bx_q$17$q;
        by_q$18$d = by_q$17$q;
        face_q$18$d = face_q$17$q;
        v_q$19$d = v_q$18$q;
        er_q$19$d = er_q$18$q;
        pad_q$19$d = pad_q$18$q;
        bx_q$19$d = bx_q$18$q;
        by_q$19$d = by_q$18$q;
        face_q$19$d = face_q$18$q;
        v_q$20$d = v_q$19$q;
        er_q$20$d = er_q$19$q;
        pad_q$20$d = pad_q$19$q;
        bx_q$20$d = bx_q$19$q;
        by_q$20$d = by_q$19$q;
        face_q$20$d = face_q$19$q;
        res_beat = v_q$20$q;
        res_valid = v_q$20$q & ~pad_q$20$q;
        px_valid = v_q$20$q & er_q$20$q & ~pad_q$20$q;
        px_x = bx_q$20$q;
        px_y = by_q$20$q;
        px_face = face_q$20$q;
    end
    
endmodule // top$lanes$0$ctl
module top$lanes$0$ctl$bx_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$0
module top$lanes$0$ctl$bx_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$1
module top$lanes$0$ctl$bx_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$10
module top$lanes$0$ctl$bx_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$11
module top$lanes$0$ctl$bx_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$12
module top$lanes$0$ctl$bx_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$13
module top$lanes$0$ctl$bx_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$14
module top$lanes$0$ctl$bx_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$15
module top$lanes$0$ctl$bx_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$16
module top$lanes$0$ctl$bx_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$17
module top$lanes$0$ctl$bx_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$18
module top$lanes$0$ctl$bx_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$19
module top$lanes$0$ctl$bx_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$2
module top$lanes$0$ctl$bx_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$20
module top$lanes$0$ctl$bx_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$3
module top$lanes$0$ctl$bx_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$4
module top$lanes$0$ctl$bx_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$5
module top$lanes$0$ctl$bx_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$6
module top$lanes$0$ctl$bx_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$7
module top$lanes$0$ctl$bx_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$8
module top$lanes$0$ctl$bx_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$bx_q$9
module top$lanes$0$ctl$by_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$0
module top$lanes$0$ctl$by_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$1
module top$lanes$0$ctl$by_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$10
module top$lanes$0$ctl$by_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$11
module top$lanes$0$ctl$by_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$12
module top$lanes$0$ctl$by_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$13
module top$lanes$0$ctl$by_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$14
module top$lanes$0$ctl$by_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$15
module top$lanes$0$ctl$by_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$16
module top$lanes$0$ctl$by_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$17
module top$lanes$0$ctl$by_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$18
module top$lanes$0$ctl$by_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$19
module top$lanes$0$ctl$by_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$2
module top$lanes$0$ctl$by_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$20
module top$lanes$0$ctl$by_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$3
module top$lanes$0$ctl$by_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$4
module top$lanes$0$ctl$by_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$5
module top$lanes$0$ctl$by_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$6
module top$lanes$0$ctl$by_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$7
module top$lanes$0$ctl$by_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$8
module top$lanes$0$ctl$by_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$by_q$9
module top$lanes$0$ctl$dxm_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxm_q$0
module top$lanes$0$ctl$dxm_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxm_q$1
module top$lanes$0$ctl$dxm_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxm_q$2
module top$lanes$0$ctl$dxm_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxm_q$3
module top$lanes$0$ctl$dxm_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxm_q$4
module top$lanes$0$ctl$dxm_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxm_q$5
module top$lanes$0$ctl$dxm_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxm_q$6
module top$lanes$0$ctl$dxm_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxm_q$7
module top$lanes$0$ctl$dxm_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxm_q$8
module top$lanes$0$ctl$dxm_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxm_q$9
module top$lanes$0$ctl$dxn_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxn_q$0
module top$lanes$0$ctl$dxn_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxn_q$1
module top$lanes$0$ctl$dxn_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxn_q$2
module top$lanes$0$ctl$dxn_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxn_q$3
module top$lanes$0$ctl$dxn_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxn_q$4
module top$lanes$0$ctl$dxn_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxn_q$5
module top$lanes$0$ctl$dxn_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxn_q$6
module top$lanes$0$ctl$dxn_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxn_q$7
module top$lanes$0$ctl$dxn_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dxn_q$8
module top$lanes$0$ctl$dym_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dym_q$0
module top$lanes$0$ctl$dym_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dym_q$1
module top$lanes$0$ctl$dym_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dym_q$2
module top$lanes$0$ctl$dym_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dym_q$3
module top$lanes$0$ctl$dym_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dym_q$4
module top$lanes$0$ctl$dym_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dym_q$5
module top$lanes$0$ctl$dym_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dym_q$6
module top$lanes$0$ctl$dym_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dym_q$7
module top$lanes$0$ctl$dym_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dym_q$8
module top$lanes$0$ctl$dym_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dym_q$9
module top$lanes$0$ctl$dyn_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dyn_q$0
module top$lanes$0$ctl$dyn_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dyn_q$1
module top$lanes$0$ctl$dyn_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dyn_q$2
module top$lanes$0$ctl$dyn_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dyn_q$3
module top$lanes$0$ctl$dyn_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dyn_q$4
module top$lanes$0$ctl$dyn_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dyn_q$5
module top$lanes$0$ctl$dyn_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dyn_q$6
module top$lanes$0$ctl$dyn_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dyn_q$7
module top$lanes$0$ctl$dyn_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$dyn_q$8
module top$lanes$0$ctl$er_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$0
module top$lanes$0$ctl$er_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$1
module top$lanes$0$ctl$er_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$10
module top$lanes$0$ctl$er_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$11
module top$lanes$0$ctl$er_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$12
module top$lanes$0$ctl$er_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$13
module top$lanes$0$ctl$er_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$14
module top$lanes$0$ctl$er_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$15
module top$lanes$0$ctl$er_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$16
module top$lanes$0$ctl$er_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$17
module top$lanes$0$ctl$er_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$18
module top$lanes$0$ctl$er_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$19
module top$lanes$0$ctl$er_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$2
module top$lanes$0$ctl$er_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$20
module top$lanes$0$ctl$er_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$3
module top$lanes$0$ctl$er_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$4
module top$lanes$0$ctl$er_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$5
module top$lanes$0$ctl$er_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$6
module top$lanes$0$ctl$er_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$7
module top$lanes$0$ctl$er_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$8
module top$lanes$0$ctl$er_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$er_q$9
module top$lanes$0$ctl$face_q$0(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$0
module top$lanes$0$ctl$face_q$1(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$1
module top$lanes$0$ctl$face_q$10(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$10
module top$lanes$0$ctl$face_q$11(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$11
module top$lanes$0$ctl$face_q$12(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$12
module top$lanes$0$ctl$face_q$13(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$13
module top$lanes$0$ctl$face_q$14(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$14
module top$lanes$0$ctl$face_q$15(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$15
module top$lanes$0$ctl$face_q$16(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$16
module top$lanes$0$ctl$face_q$17(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$17
module top$lanes$0$ctl$face_q$18(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$18
module top$lanes$0$ctl$face_q$19(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$19
module top$lanes$0$ctl$face_q$2(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$2
module top$lanes$0$ctl$face_q$20(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$20
module top$lanes$0$ctl$face_q$3(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$3
module top$lanes$0$ctl$face_q$4(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$4
module top$lanes$0$ctl$face_q$5(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$5
module top$lanes$0$ctl$face_q$6(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$6
module top$lanes$0$ctl$face_q$7(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$7
module top$lanes$0$ctl$face_q$8(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$8
module top$lanes$0$ctl$face_q$9(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$ctl$face_q$9
module top$lanes$0$ctl$nx_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$ctl$nx_last
module top$lanes$0$ctl$ny_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$ctl$ny_last
module top$lanes$0$ctl$pad_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$0
module top$lanes$0$ctl$pad_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$1
module top$lanes$0$ctl$pad_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$10
module top$lanes$0$ctl$pad_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$11
module top$lanes$0$ctl$pad_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$12
module top$lanes$0$ctl$pad_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$13
module top$lanes$0$ctl$pad_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$14
module top$lanes$0$ctl$pad_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$15
module top$lanes$0$ctl$pad_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$16
module top$lanes$0$ctl$pad_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$17
module top$lanes$0$ctl$pad_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$18
module top$lanes$0$ctl$pad_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$19
module top$lanes$0$ctl$pad_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$2
module top$lanes$0$ctl$pad_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$20
module top$lanes$0$ctl$pad_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$3
module top$lanes$0$ctl$pad_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$4
module top$lanes$0$ctl$pad_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$5
module top$lanes$0$ctl$pad_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$6
module top$lanes$0$ctl$pad_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$7
module top$lanes$0$ctl$pad_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$8
module top$lanes$0$ctl$pad_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$pad_q$9
module top$lanes$0$ctl$sel_q$0(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$ctl$sel_q$0
module top$lanes$0$ctl$sel_q$1(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$ctl$sel_q$1
module top$lanes$0$ctl$sel_q$2(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$ctl$sel_q$2
module top$lanes$0$ctl$sel_q$3(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$ctl$sel_q$3
module top$lanes$0$ctl$sr_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$sr_q$0
module top$lanes$0$ctl$sr_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$sr_q$1
module top$lanes$0$ctl$sr_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$sr_q$2
module top$lanes$0$ctl$sr_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$sr_q$3
module top$lanes$0$ctl$sr_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$sr_q$4
module top$lanes$0$ctl$sr_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$sr_q$5
module top$lanes$0$ctl$sr_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$sr_q$6
module top$lanes$0$ctl$sr_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$sr_q$7
module top$lanes$0$ctl$sr_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$sr_q$8
module top$lanes$0$ctl$v_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$0
module top$lanes$0$ctl$v_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$1
module top$lanes$0$ctl$v_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$10
module top$lanes$0$ctl$v_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$11
module top$lanes$0$ctl$v_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$12
module top$lanes$0$ctl$v_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$13
module top$lanes$0$ctl$v_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$14
module top$lanes$0$ctl$v_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$15
module top$lanes$0$ctl$v_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$16
module top$lanes$0$ctl$v_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$17
module top$lanes$0$ctl$v_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$18
module top$lanes$0$ctl$v_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$19
module top$lanes$0$ctl$v_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$2
module top$lanes$0$ctl$v_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$20
module top$lanes$0$ctl$v_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$3
module top$lanes$0$ctl$v_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$4
module top$lanes$0$ctl$v_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$5
module top$lanes$0$ctl$v_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$6
module top$lanes$0$ctl$v_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$7
module top$lanes$0$ctl$v_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$8
module top$lanes$0$ctl$v_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$v_q$9
module top$lanes$0$ctl$x_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$x_q$0
module top$lanes$0$ctl$x_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$x_q$1
module top$lanes$0$ctl$x_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$x_q$2
module top$lanes$0$ctl$x_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$x_q$3
module top$lanes$0$ctl$x_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$x_q$4
module top$lanes$0$ctl$x_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$x_q$5
module top$lanes$0$ctl$x_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$x_q$6
module top$lanes$0$ctl$x_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$x_q$7
module top$lanes$0$ctl$x_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$x_q$8
module top$lanes$0$ctl$x_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$x_q$9
module top$lanes$0$ctl$y_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$y_q$0
module top$lanes$0$ctl$y_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$y_q$1
module top$lanes$0$ctl$y_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$y_q$2
module top$lanes$0$ctl$y_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$y_q$3
module top$lanes$0$ctl$y_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$y_q$4
module top$lanes$0$ctl$y_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$y_q$5
module top$lanes$0$ctl$y_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$y_q$6
module top$lanes$0$ctl$y_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$y_q$7
module top$lanes$0$ctl$y_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$ctl$y_q$8
module top$lanes$0$feed(clock,beats,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,o_valid,o_value,o_x,o_y,o_pad,o_invalid,o_sr,o_er,o_edge,o_face,o_base_x,o_base_y,o_dx_neg,o_dx_mag,o_dy_neg,o_dy_mag,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  o_valid;
    output reg  [15:0] o_value;
    output reg  [15:0] o_x;
    output reg  [15:0] o_y;
    output reg  o_pad;
    output reg  o_invalid;
    output reg  o_sr;
    output reg  o_er;
    output reg  o_edge;
    output reg  [2:0] o_face;
    output reg  [15:0] o_base_x;
    output reg  [15:0] o_base_y;
    output reg  o_dx_neg;
    output reg  [15:0] o_dx_mag;
    output reg  o_dy_neg;
    output reg  [15:0] o_dy_mag;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  use_gradient = 1'b0;
    
    // Stub signals
    reg  abc$clock;
    reg  [63:0] abc$beats;
    reg  [15:0] abc$value;
    reg  [15:0] abc$x;
    reg  [15:0] abc$from_left_xm;
    reg  [15:0] abc$from_left_ym;
    reg  [15:0] abc$from_left_zm;
    reg  [15:0] abc$from_right_xp;
    reg  [15:0] abc$from_right_yp;
    reg  [15:0] abc$from_right_zp;
    wire  [15:0] abc$to_right_xm = 'h0;
    wire  [15:0] abc$to_right_ym = 'h0;
    wire  [15:0] abc$to_right_zm = 'h0;
    wire  [15:0] abc$to_left_xp = 'h0;
    wire  [15:0] abc$to_left_yp = 'h0;
    wire  [15:0] abc$to_left_zp = 'h0;
    wire  [15:0] abc$o_value = 'h0;
    wire  abc$gx_neg = 'h0;
    wire  [15:0] abc$gx_mag = 'h0;
    wire  abc$gy_neg = 'h0;
    wire  [15:0] abc$gy_mag = 'h0;
    wire  abc$gz_neg = 'h0;
    wire  [15:0] abc$gz_mag = 'h0;
    
    // Sub module instances
    
    // Update code
    reg  [15:0] o_value_pass;
    always @(*) begin
        abc$clock = clock;
        abc$beats = beats;
        abc$value = value;
        abc$x = x;
        abc$from_left_xm = g_from_left_xm;
        abc$from_left_ym = g_from_left_ym;
        abc$from_left_zm = g_from_left_zm;
        abc$from_right_xp = g_from_right_xp;
        abc$from_right_yp = g_from_right_yp;
        abc$from_right_zp = g_from_right_zp;
        g_to_right_xm = abc$to_right_xm;
        g_to_right_ym = abc$to_right_ym;
        g_to_right_zm = abc$to_right_zm;
        g_to_left_xp = abc$to_left_xp;
        g_to_left_yp = abc$to_left_yp;
        g_to_left_zp = abc$to_left_zp;
        gx_neg = abc$gx_neg;
        gx_mag = abc$gx_mag;
        gy_neg = abc$gy_neg;
        gy_mag = abc$gy_mag;
        gz_neg = abc$gz_neg;
        gz_mag = abc$gz_mag;
        if (use_gradient) begin
            o_value_pass = abc$o_value;
        end
        else begin
            o_value_pass = value;
        end
        o_valid = beat_valid & ~halo;
        o_x = x;
        o_y = y;
        o_pad = pad;
        o_invalid = invalid;
        o_sr = sr;
        o_er = er;
        o_edge = at_edge;
        o_face = face;
        o_base_x = base_x;
        o_base_y = base_y;
        o_dx_neg = dx_neg;
        o_dx_mag = dx_mag;
        o_dy_neg = dy_neg;
        o_dy_mag = dy_mag;
        o_value = o_value_pass;
    end
    
endmodule // top$lanes$0$feed
module top$lanes$1(clock,host_write,host_address,host_data,dims,beats,order,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,res_beat,res_valid,res,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [63:0] dims;
    input wire  [63:0] beats;
    input wire  [63:0] order;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  res_beat;
    output reg  res_valid;
    output reg  [63:0] res;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Constant declarations
    localparam  coord_mask = 16'hff;
    
    // Stub signals
    reg  feed$clock;
    reg  [63:0] feed$beats;
    reg  feed$beat_valid;
    reg  [15:0] feed$value;
    reg  [15:0] feed$x;
    reg  [15:0] feed$y;
    reg  feed$pad;
    reg  feed$invalid;
    reg  feed$halo;
    reg  feed$sr;
    reg  feed$er;
    reg  [15:0] feed$base_x;
    reg  [15:0] feed$base_y;
    reg  [2:0] feed$face;
    reg  feed$at_edge;
    reg  feed$dx_neg;
    reg  [15:0] feed$dx_mag;
    reg  feed$dy_neg;
    reg  [15:0] feed$dy_mag;
    reg  [15:0] feed$g_from_left_xm;
    reg  [15:0] feed$g_from_left_ym;
    reg  [15:0] feed$g_from_left_zm;
    reg  [15:0] feed$g_from_right_xp;
    reg  [15:0] feed$g_from_right_yp;
    reg  [15:0] feed$g_from_right_zp;
    wire  [15:0] feed$g_to_right_xm;
    wire  [15:0] feed$g_to_right_ym;
    wire  [15:0] feed$g_to_right_zm;
    wire  [15:0] feed$g_to_left_xp;
    wire  [15:0] feed$g_to_left_yp;
    wire  [15:0] feed$g_to_left_zp;
    wire  feed$o_valid;
    wire  [15:0] feed$o_value;
    wire  [15:0] feed$o_x;
    wire  [15:0] feed$o_y;
    wire  feed$o_pad;
    wire  feed$o_invalid;
    wire  feed$o_sr;
    wire  feed$o_er;
    wire  feed$o_edge;
    wire  [2:0] feed$o_face;
    wire  [15:0] feed$o_base_x;
    wire  [15:0] feed$o_base_y;
    wire  feed$o_dx_neg;
    wire  [15:0] feed$o_dx_mag;
    wire  feed$o_dy_neg;
    wire  [15:0] feed$o_dy_mag;
    wire  feed$gx_neg;
    wire  [15:0] feed$gx_mag;
    wire  feed$gy_neg;
    wire  [15:0] feed$gy_mag;
    wire  feed$gz_neg;
    wire  [15:0] feed$gz_mag;
    reg  shader$clock;
    reg  shader$host_write;
    reg  [23:0] shader$host_address;
    reg  [63:0] shader$host_data;
    reg  [15:0] shader$value;
    reg  shader$invalid;
    reg  shader$at_edge;
    reg  shader$gx_neg;
    reg  [31:0] shader$gx_mag;
    reg  shader$gy_neg;
    reg  [31:0] shader$gy_mag;
    reg  shader$gz_neg;
    reg  [31:0] shader$gz_mag;
    wire  [31:0] shader$r;
    wire  [15:0] shader$g;
    wire  [15:0] shader$b;
    wire  [15:0] shader$a;
    wire  shader$valid;
    reg  ctl$clock;
    reg  ctl$valid;
    reg  ctl$er;
    reg  ctl$pad;
    reg  [15:0] ctl$base_x;
    reg  [15:0] ctl$base_y;
    reg  [2:0] ctl$face;
    reg  [15:0] ctl$x;
    reg  [15:0] ctl$y;
    reg  ctl$sr;
    reg  ctl$dx_neg;
    reg  [15:0] ctl$dx_mag;
    reg  ctl$dy_neg;
    reg  [15:0] ctl$dy_mag;
    reg  [63:0] ctl$dims;
    reg  [15:0] ctl$coord_mask;
    wire  [15:0] ctl$x_t;
    wire  [15:0] ctl$dx_mag_t;
    wire  [15:0] ctl$dy_mag_t;
    wire  [6:0] ctl$sel_t$0;
    wire  [6:0] ctl$sel_t$1;
    wire  [6:0] ctl$sel_t$2;
    wire  [6:0] ctl$sel_t$3;
    wire  ctl$res_beat;
    wire  ctl$res_valid;
    wire  ctl$px_valid;
    wire  [15:0] ctl$px_x;
    wire  [15:0] ctl$px_y;
    wire  [2:0] ctl$px_face;
    reg  taps$clock;
    reg  [63:0] taps$beats;
    reg  [15:0] taps$x;
    reg  [63:0] taps$res;
    reg  taps$res_beat;
    wire  [63:0] taps$t0s0;
    reg  [63:0] taps$t0i1;
    wire  [63:0] taps$t1s0;
    wire  [63:0] taps$t1s1;
    reg  [63:0] taps$t1i1;
    reg  [63:0] taps$t1i2;
    wire  [63:0] taps$t3s0;
    wire  [63:0] taps$t3s1;
    reg  [63:0] taps$t3i1;
    reg  [63:0] taps$t3i2;
    wire  [63:0] taps$t5s0;
    wire  [63:0] taps$t5s1;
    wire  [63:0] taps$t5s2;
    reg  [63:0] taps$t5i1;
    reg  [63:0] taps$t5i2;
    reg  [63:0] taps$t5i3;
    wire  [63:0] taps$t6s0;
    reg  [63:0] taps$t6i1;
    wire  [63:0] taps$t7s0;
    reg  [63:0] taps$t7i1;
    wire  [63:0] taps$t8s0;
    reg  [63:0] taps$t8i1;
    reg  [63:0] taps$t8il;
    wire  [63:0] taps$a$0;
    wire  [63:0] taps$a$1;
    wire  [63:0] taps$a$2;
    wire  [63:0] taps$a$3;
    wire  [63:0] taps$a$4;
    wire  [63:0] taps$a$5;
    wire  [63:0] taps$a$6;
    wire  [63:0] taps$a$7;
    wire  [63:0] taps$a$8;
    reg  [63:0] cells$a$0;
    reg  [63:0] cells$a$1;
    reg  [63:0] cells$a$2;
    reg  [63:0] cells$a$3;
    reg  [63:0] cells$a$4;
    reg  [63:0] cells$a$5;
    reg  [63:0] cells$a$6;
    reg  [63:0] cells$a$7;
    reg  [63:0] cells$a$8;
    reg  [6:0] cells$sel$0;
    reg  [6:0] cells$sel$1;
    reg  [6:0] cells$sel$2;
    reg  [6:0] cells$sel$3;
    wire  [31:0] cells$c00$0;
    wire  [31:0] cells$c00$1;
    wire  [31:0] cells$c00$2;
    wire  [31:0] cells$c00$3;
    wire  [31:0] cells$c10$0;
    wire  [31:0] cells$c10$1;
    wire  [31:0] cells$c10$2;
    wire  [31:0] cells$c10$3;
    wire  [31:0] cells$c01$0;
    wire  [31:0] cells$c01$1;
    wire  [31:0] cells$c01$2;
    wire  [31:0] cells$c01$3;
    wire  [31:0] cells$c11$0;
    wire  [31:0] cells$c11$1;
    wire  [31:0] cells$c11$2;
    wire  [31:0] cells$c11$3;
    reg  [63:0] cells$order;
    reg  bilinear$clock;
    reg  [31:0] bilinear$c00$0;
    reg  [31:0] bilinear$c00$1;
    reg  [31:0] bilinear$c00$2;
    reg  [31:0] bilinear$c00$3;
    reg  [31:0] bilinear$c10$0;
    reg  [31:0] bilinear$c10$1;
    reg  [31:0] bilinear$c10$2;
    reg  [31:0] bilinear$c10$3;
    reg  [31:0] bilinear$c01$0;
    reg  [31:0] bilinear$c01$1;
    reg  [31:0] bilinear$c01$2;
    reg  [31:0] bilinear$c01$3;
    reg  [31:0] bilinear$c11$0;
    reg  [31:0] bilinear$c11$1;
    reg  [31:0] bilinear$c11$2;
    reg  [31:0] bilinear$c11$3;
    reg  [15:0] bilinear$wx;
    reg  [15:0] bilinear$wy;
    wire  [31:0] bilinear$out$0;
    wire  [31:0] bilinear$out$1;
    wire  [31:0] bilinear$out$2;
    wire  [31:0] bilinear$out$3;
    reg  compositor$clock;
    reg  [31:0] compositor$acc_r;
    reg  [15:0] compositor$acc_g;
    reg  [15:0] compositor$acc_b;
    reg  [15:0] compositor$acc_a;
    reg  [31:0] compositor$new_r;
    reg  [15:0] compositor$new_g;
    reg  [15:0] compositor$new_b;
    reg  [15:0] compositor$new_a;
    reg  compositor$new_valid;
    wire  [31:0] compositor$out_r;
    wire  [15:0] compositor$out_g;
    wire  [15:0] compositor$out_b;
    wire  [15:0] compositor$out_a;
    reg  [63:0] compositor$order;
    
    // Sub module instances
    top$lanes$1$feed feed(
        .clock(feed$clock),
        .beats(feed$beats),
        .beat_valid(feed$beat_valid),
        .value(feed$value),
        .x(feed$x),
        .y(feed$y),
        .pad(feed$pad),
        .invalid(feed$invalid),
        .halo(feed$halo),
        .sr(feed$sr),
        .er(feed$er),
        .base_x(feed$base_x),
        .base_y(feed$base_y),
        .face(feed$face),
        .at_edge(feed$at_edge),
        .dx_neg(feed$dx_neg),
        .dx_mag(feed$dx_mag),
        .dy_neg(feed$dy_neg),
        .dy_mag(feed$dy_mag),
        .g_from_left_xm(feed$g_from_left_xm),
        .g_from_left_ym(feed$g_from_left_ym),
        .g_from_left_zm(feed$g_from_left_zm),
        .g_from_right_xp(feed$g_from_right_xp),
        .g_from_right_yp(feed$g_from_right_yp),
        .g_from_right_zp(feed$g_from_right_zp),
        .g_to_right_xm(feed$g_to_right_xm),
        .g_to_right_ym(feed$g_to_right_ym),
        .g_to_right_zm(feed$g_to_right_zm),
        .g_to_left_xp(feed$g_to_left_xp),
        .g_to_left_yp(feed$g_to_left_yp),
        .g_to_left_zp(feed$g_to_left_zp),
        .o_valid(feed$o_valid),
        .o_value(feed$o_value),
        .o_x(feed$o_x),
        .o_y(feed$o_y),
        .o_pad(feed$o_pad),
        .o_invalid(feed$o_invalid),
        .o_sr(feed$o_sr),
        .o_er(feed$o_er),
        .o_edge(feed$o_edge),
        .o_face(feed$o_face),
        .o_base_x(feed$o_base_x),
        .o_base_y(feed$o_base_y),
        .o_dx_neg(feed$o_dx_neg),
        .o_dx_mag(feed$o_dx_mag),
        .o_dy_neg(feed$o_dy_neg),
        .o_dy_mag(feed$o_dy_mag),
        .gx_neg(feed$gx_neg),
        .gx_mag(feed$gx_mag),
        .gy_neg(feed$gy_neg),
        .gy_mag(feed$gy_mag),
        .gz_neg(feed$gz_neg),
        .gz_mag(feed$gz_mag)
    );
    top$lanes$1$shader shader(
        .clock(shader$clock),
        .host_write(shader$host_write),
        .host_address(shader$host_address),
        .host_data(shader$host_data),
        .value(shader$value),
        .invalid(shader$invalid),
        .at_edge(shader$at_edge),
        .gx_neg(shader$gx_neg),
        .gx_mag(shader$gx_mag),
        .gy_neg(shader$gy_neg),
        .gy_mag(shader$gy_mag),
        .gz_neg(shader$gz_neg),
        .gz_mag(shader$gz_mag),
        .r(shader$r),
        .g(shader$g),
        .b(shader$b),
        .a(shader$a),
        .valid(shader$valid)
    );
    top$lanes$1$ctl ctl(
        .clock(ctl$clock),
        .valid(ctl$valid),
        .er(ctl$er),
        .pad(ctl$pad),
        .base_x(ctl$base_x),
        .base_y(ctl$base_y),
        .face(ctl$face),
        .x(ctl$x),
        .y(ctl$y),
        .sr(ctl$sr),
        .dx_neg(ctl$dx_neg),
        .dx_mag(ctl$dx_mag),
        .dy_neg(ctl$dy_neg),
        .dy_mag(ctl$dy_mag),
        .dims(ctl$dims),
        .coord_mask(ctl$coord_mask),
        .x_t(ctl$x_t),
        .dx_mag_t(ctl$dx_mag_t),
        .dy_mag_t(ctl$dy_mag_t),
        .sel_t$0(ctl$sel_t$0),
        .sel_t$1(ctl$sel_t$1),
        .sel_t$2(ctl$sel_t$2),
        .sel_t$3(ctl$sel_t$3),
        .res_beat(ctl$res_beat),
        .res_valid(ctl$res_valid),
        .px_valid(ctl$px_valid),
        .px_x(ctl$px_x),
        .px_y(ctl$px_y),
        .px_face(ctl$px_face)
    );
    top$lanes$1$taps taps(
        .clock(taps$clock),
        .beats(taps$beats),
        .x(taps$x),
        .res(taps$res),
        .res_beat(taps$res_beat),
        .t0s0(taps$t0s0),
        .t0i1(taps$t0i1),
        .t1s0(taps$t1s0),
        .t1s1(taps$t1s1),
        .t1i1(taps$t1i1),
        .t1i2(taps$t1i2),
        .t3s0(taps$t3s0),
        .t3s1(taps$t3s1),
        .t3i1(taps$t3i1),
        .t3i2(taps$t3i2),
        .t5s0(taps$t5s0),
        .t5s1(taps$t5s1),
        .t5s2(taps$t5s2),
        .t5i1(taps$t5i1),
        .t5i2(taps$t5i2),
        .t5i3(taps$t5i3),
        .t6s0(taps$t6s0),
        .t6i1(taps$t6i1),
        .t7s0(taps$t7s0),
        .t7i1(taps$t7i1),
        .t8s0(taps$t8s0),
        .t8i1(taps$t8i1),
        .t8il(taps$t8il),
        .a$0(taps$a$0),
        .a$1(taps$a$1),
        .a$2(taps$a$2),
        .a$3(taps$a$3),
        .a$4(taps$a$4),
        .a$5(taps$a$5),
        .a$6(taps$a$6),
        .a$7(taps$a$7),
        .a$8(taps$a$8)
    );
    top$lanes$1$cells cells(
        .a$0(cells$a$0),
        .a$1(cells$a$1),
        .a$2(cells$a$2),
        .a$3(cells$a$3),
        .a$4(cells$a$4),
        .a$5(cells$a$5),
        .a$6(cells$a$6),
        .a$7(cells$a$7),
        .a$8(cells$a$8),
        .sel$0(cells$sel$0),
        .sel$1(cells$sel$1),
        .sel$2(cells$sel$2),
        .sel$3(cells$sel$3),
        .c00$0(cells$c00$0),
        .c00$1(cells$c00$1),
        .c00$2(cells$c00$2),
        .c00$3(cells$c00$3),
        .c10$0(cells$c10$0),
        .c10$1(cells$c10$1),
        .c10$2(cells$c10$2),
        .c10$3(cells$c10$3),
        .c01$0(cells$c01$0),
        .c01$1(cells$c01$1),
        .c01$2(cells$c01$2),
        .c01$3(cells$c01$3),
        .c11$0(cells$c11$0),
        .c11$1(cells$c11$1),
        .c11$2(cells$c11$2),
        .c11$3(cells$c11$3),
        .order(cells$order)
    );
    top$lanes$1$bilinear bilinear(
        .clock(bilinear$clock),
        .c00$0(bilinear$c00$0),
        .c00$1(bilinear$c00$1),
        .c00$2(bilinear$c00$2),
        .c00$3(bilinear$c00$3),
        .c10$0(bilinear$c10$0),
        .c10$1(bilinear$c10$1),
        .c10$2(bilinear$c10$2),
        .c10$3(bilinear$c10$3),
        .c01$0(bilinear$c01$0),
        .c01$1(bilinear$c01$1),
        .c01$2(bilinear$c01$2),
        .c01$3(bilinear$c01$3),
        .c11$0(bilinear$c11$0),
        .c11$1(bilinear$c11$1),
        .c11$2(bilinear$c11$2),
        .c11$3(bilinear$c11$3),
        .wx(bilinear$wx),
        .wy(bilinear$wy),
        .out$0(bilinear$out$0),
        .out$1(bilinear$out$1),
        .out$2(bilinear$out$2),
        .out$3(bilinear$out$3)
    );
    top$lanes$1$compositor compositor(
        .clock(compositor$clock),
        .acc_r(compositor$acc_r),
        .acc_g(compositor$acc_g),
        .acc_b(compositor$acc_b),
        .acc_a(compositor$acc_a),
        .new_r(compositor$new_r),
        .new_g(compositor$new_g),
        .new_b(compositor$new_b),
        .new_a(compositor$new_a),
        .new_valid(compositor$new_valid),
        .out_r(compositor$out_r),
        .out_g(compositor$out_g),
        .out_b(compositor$out_b),
        .out_a(compositor$out_a),
        .order(compositor$order)
    );
    
    // Update code
    always @(*) begin
        feed$clock = clock;
        feed$beats = beats;
        feed$beat_valid = beat_valid;
        feed$value = value;
        feed$x = x;
        feed$y = y;
        feed$pad = pad;
        feed$invalid = invalid;
        feed$halo = halo;
        feed$sr = sr;
        feed$er = er;
        feed$base_x = base_x;
        feed$base_y = base_y;
        feed$face = face;
        feed$at_edge = at_edge;
        feed$dx_neg = dx_neg;
        feed$dx_mag = dx_mag;
        feed$dy_neg = dy_neg;
        feed$dy_mag = dy_mag;
        feed$g_from_left_xm = g_from_left_xm;
        feed$g_from_left_ym = g_from_left_ym;
        feed$g_from_left_zm = g_from_left_zm;
        feed$g_from_right_xp = g_from_right_xp;
        feed$g_from_right_yp = g_from_right_yp;
        feed$g_from_right_zp = g_from_right_zp;
        g_to_right_xm = feed$g_to_right_xm;
        g_to_right_ym = feed$g_to_right_ym;
        g_to_right_zm = feed$g_to_right_zm;
        g_to_left_xp = feed$g_to_left_xp;
        g_to_left_yp = feed$g_to_left_yp;
        g_to_left_zp = feed$g_to_left_zp;
        shader$clock = clock;
        shader$host_write = host_write;
        shader$host_address = host_address;
        shader$host_data = host_data;
        shader$value = feed$o_value;
        shader$invalid = feed$o_invalid;
        shader$at_edge = feed$o_edge;
        shader$gx_neg = feed$gx_neg;
        shader$gx_mag = 32'(feed$gx_mag);
        shader$gy_neg = feed$gy_neg;
        shader$gy_mag = 32'(feed$gy_mag);
        shader$gz_neg = feed$gz_neg;
        shader$gz_mag = 32'(feed$gz_mag);
        ctl$clock = clock;
        ctl$valid = feed$o_valid;
        ctl$er = feed$o_er;
        ctl$pad = feed$o_pad;
        ctl$coord_mask = coord_mask;
        ctl$base_x = feed$o_base_x;
        ctl$base_y = feed$o_base_y;
        ctl$face = feed$o_face;
        ctl$x = feed$o_x;
        ctl$y = feed$o_y;
        ctl$sr = feed$o_sr;
        ctl$dx_neg = feed$o_dx_neg;
        ctl$dx_mag = feed$o_dx_mag;
        ctl$dy_neg = feed$o_dy_neg;
        ctl$dy_mag = feed$o_dy_mag;
        ctl$dims = dims;
        taps$clock = clock;
        taps$beats = beats;
        taps$x = ctl$x_t;
        t0s0 = taps$t0s0;
        taps$t0i1 = t0i1;
        t1s0 = taps$t1s0;
        t1s1 = taps$t1s1;
        taps$t1i1 = t1i1;
        taps$t1i2 = t1i2;
        t3s0 = taps$t3s0;
        t3s1 = taps$t3s1;
        taps$t3i1 = t3i1;
        taps$t3i2 = t3i2;
        t5s0 = taps$t5s0;
        t5s1 = taps$t5s1;
        t5s2 = taps$t5s2;
        taps$t5i1 = t5i1;
        taps$t5i2 = t5i2;
        taps$t5i3 = t5i3;
        t6s0 = taps$t6s0;
        taps$t6i1 = t6i1;
        t7s0 = taps$t7s0;
        taps$t7i1 = t7i1;
        t8s0 = taps$t8s0;
        taps$t8i1 = t8i1;
        taps$t8il = t8il;
        cells$a$0 = taps$a$0;
        cells$a$1 = taps$a$1;
        cells$a$2 = taps$a$2;
        cells$a$3 = taps$a$3;
        cells$a$4 = taps$a$4;
        cells$a$5 = taps$a$5;
        cells$a$6 = taps$a$6;
        cells$a$7 = taps$a$7;
        cells$a$8 = taps$a$8;
        cells$order = order;
        cells$sel$0 = ctl$sel_t$0;
        cells$sel$1 = ctl$sel_t$1;
        cells$sel$2 = ctl$sel_t$2;
        cells$sel$3 = ctl$sel_t$3;
        bilinear$clock = clock;
        bilinear$c00$0 = cells$c00$0;
        bilinear$c10$0 = cells$c10$0;
        bilinear$c01$0 = cells$c01$0;
        bilinear$c11$0 = cells$c11$0;
        bilinear$c00$1 = cells$c00$1;
        bilinear$c10$1 = cells$c10$1;
        bilinear$c01$1 = cells$c01$1;
        bilinear$c11$1 = cells$c11$1;
        bilinear$c00$2 = cells$c00$2;
        bilinear$c10$2 = cells$c10$2;
        bilinear$c01$2 = cells$c01$2;
        bilinear$c11$2 = cells$c11$2;
        bilinear$c00$3 = cells$c00$3;
        bilinear$c10$3 = cells$c10$3;
        bilinear$c01$3 = cells$c01$3;
        bilinear$c11$3 = cells$c11$3;
        bilinear$wx = ctl$dx_mag_t;
        bilinear$wy = ctl$dy_mag_t;
        compositor$clock = clock;
        compositor$order = order;
        compositor$acc_r = bilinear$out$0;
        compositor$acc_g = 16'(bilinear$out$1);
        compositor$acc_b = 16'(bilinear$out$2);
        compositor$acc_a = 16'(bilinear$out$3);
        compositor$new_r = shader$r;
        compositor$new_g = shader$g;
        compositor$new_b = shader$b;
        compositor$new_a = shader$a;
        compositor$new_valid = shader$valid;
        res = 64'(compositor$out_r) | (64'(compositor$out_g) << 'h10) | (64'(compositor$out_b) << 'h20) | (64'(compositor$out_a) << 'h30);
        taps$res = res;
        taps$res_beat = ctl$res_beat;
        res_beat = ctl$res_beat;
        res_valid = ctl$res_valid;
        px_valid = ctl$px_valid;
        px_x = ctl$px_x;
        px_y = ctl$px_y;
        px_face = ctl$px_face;
    end
    
endmodule // top$lanes$1
module top$lanes$1$cells(a$0,a$1,a$2,a$3,a$4,a$5,a$6,a$7,a$8,sel$0,sel$1,sel$2,sel$3,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,order);
    
    // Module arguments
    input wire  [63:0] a$0;
    input wire  [63:0] a$1;
    input wire  [63:0] a$2;
    input wire  [63:0] a$3;
    input wire  [63:0] a$4;
    input wire  [63:0] a$5;
    input wire  [63:0] a$6;
    input wire  [63:0] a$7;
    input wire  [63:0] a$8;
    input wire  [6:0] sel$0;
    input wire  [6:0] sel$1;
    input wire  [6:0] sel$2;
    input wire  [6:0] sel$3;
    output reg  [31:0] c00$0;
    output reg  [31:0] c00$1;
    output reg  [31:0] c00$2;
    output reg  [31:0] c00$3;
    output reg  [31:0] c10$0;
    output reg  [31:0] c10$1;
    output reg  [31:0] c10$2;
    output reg  [31:0] c10$3;
    output reg  [31:0] c01$0;
    output reg  [31:0] c01$1;
    output reg  [31:0] c01$2;
    output reg  [31:0] c01$3;
    output reg  [31:0] c11$0;
    output reg  [31:0] c11$1;
    output reg  [31:0] c11$2;
    output reg  [31:0] c11$3;
    input wire  [63:0] order;
    
    // Constant declarations
    localparam  vmax = 64'hff;
    localparam  r_mask = 64'hffff;
    localparam  gba_mask = 64'hffff;
    
    // Local signals
    reg  [63:0] reset;
    reg  [63:0] w00$0;
    reg  [63:0] w00$1;
    reg  [63:0] w00$2;
    reg  [63:0] w00$3;
    reg  [63:0] w10$0;
    reg  [63:0] w10$1;
    reg  [63:0] w10$2;
    reg  [63:0] w10$3;
    reg  [63:0] w01$0;
    reg  [63:0] w01$1;
    reg  [63:0] w01$2;
    reg  [63:0] w01$3;
    reg  [63:0] w11$0;
    reg  [63:0] w11$1;
    reg  [63:0] w11$2;
    reg  [63:0] w11$3;
    
    // Update code
    always @(*) begin
        reset = 'h0;
        if (order['h1]) begin
            reset = vmax;
        end
        w00$0 = a$0;
        w10$0 = a$0;
        w01$0 = a$0;
        if (sel$0['h2]) begin
            if (sel$0['h1]) begin
                w10$0 = a$2;
            end
            else begin
                w10$0 = a$1;
            end
        end
        if (sel$0['h4]) begin
            if (sel$0['h3]) begin
                w01$0 = a$4;
            end
            else begin
                w01$0 = a$3;
            end
        end
        w11$0 = w01$0;
        if (sel$0['h2]) begin
            w11$0 = w10$0;
            if (sel$0['h4]) begin
                if (sel$0['h1]) begin
                    if (sel$0['h3]) begin
                        w11$0 = a$8;
                    end
                    else begin
                        w11$0 = a$6;
                    end
                end
                else if (sel$0['h3]) begin
                    w11$0 = a$7;
                end
                else begin
                    w11$0 = a$5;
                end
            end
        end
        if (sel$0['h5]) begin
            w10$0 = reset;
            w11$0 = reset;
        end
        if (sel$0['h6]) begin
            w01$0 = reset;
            w11$0 = reset;
        end
        if (sel$0['h0]) begin
            w00$0 = reset;
            w10$0 = reset;
            w01$0 = reset;
            w11$0 = reset;
        end
        w00$1 = a$0;
        w10$1 = a$0;
        w01$1 = a$0;
        if (sel$1['h2]) begin
            if (sel$1['h1]) begin
                w10$1 = a$2;
            end
            else begin
                w10$1 = a$1;
            end
        end
        if (sel$1['h4]) begin
            if (sel$1['h3]) begin
                w01$1 = a$4;
            end
            else begin
                w01$1 = a$3;
            end
        end
        w11$1 = w01$1;
        if (sel$1['h2]) begin
            w11$1 = w10$1;
            if (sel$1['h4]) begin
                if (sel$1['h1]) begin
                    if (sel$1['h3]) begin
                        w11$1 = a$8;
                    end
                    else begin
                        w11$1 = a$6;
                    end
                end
                else if (sel$1['h3]) begin
                    w11$1 = a$7;
                end
                else begin
                    w11$1 = a$5;
                end
            end
        end
        if (sel$1['h5]) begin
            w10$1 = reset;
            w11$1 = reset;
        end
        if (sel$1['h6]) begin
            w01$1 = reset;
            w11$1 = reset;
        end
        if (sel$1['h0]) begin
            w00$1 = reset;
            w10$1 = reset;
            w01$1 = reset;
            w11$1 = reset;
        end
        w00$2 = a$0;
        w10$2 = a$0;
        w01$2 = a$0;
        if (sel$2['h2]) begin
            if (sel$2['h1]) begin
                w10$2 = a$2;
            end
            else begin
                w10$2 = a$1;
            end
        end
        if (sel$2['h4]) begin
            if (sel$2['h3]) begin
                w01$2 = a$4;
            end
            else begin
                w01$2 = a$3;
            end
        end
        w11$2 = w01$2;
        if (sel$2['h2]) begin
            w11$2 = w10$2;
            if (sel$2['h4]) begin
                if (sel$2['h1]) begin
                    if (sel$2['h3]) begin
                        w11$2 = a$8;
                    end
                    else begin
                        w11$2 = a$6;
                    end
                end
                else if (sel$2['h3]) begin
                    w11$2 = a$7;
                end
                else begin
                    w11$2 = a$5;
                end
            end
        end
        if (sel$2['h5]) begin
            w10$2 = reset;
            w11$2 = reset;
        end
        if (sel$2['h6]) begin
            w01$2 = reset;
            w11$2 = reset;
        end
        if (sel$2['h0]) begin
            w00$2 = reset;
            w10$2 = reset;
            w01$2 = reset;
            w11$2 = reset;
        end
        w00$3 = a$0;
        w10$3 = a$0;
        w01$3 = a$0;
        if (sel$3['h2]) begin
            if (sel$3['h1]) begin
                w10$3 = a$2;
            end
            else begin
                w10$3 = a$1;
            end
        end
        if (sel$3['h4]) begin
            if (sel$3['h3]) begin
                w01$3 = a$4;
            end
            else begin
                w01$3 = a$3;
            end
        end
        w11$3 = w01$3;
        if (sel$3['h2]) begin
            w11$3 = w10$3;
            if (sel$3['h4]) begin
                if (sel$3['h1]) begin
                    if (sel$3['h3]) begin
                        w11$3 = a$8;
                    end
                    else begin
                        w11$3 = a$6;
                    end
                end
                else if (sel$3['h3]) begin
                    w11$3 = a$7;
                end
                else begin
                    w11$3 = a$5;
                end
            end
        end
        if (sel$3['h5]) begin
            w10$3 = reset;
            w11$3 = reset;
        end
        if (sel$3['h6]) begin
            w01$3 = reset;
            w11$3 = reset;
        end
        if (sel$3['h0]) begin
            w00$3 = reset;
            w10$3 = reset;
            w01$3 = reset;
            w11$3 = reset;
        end
        c00$0 = 32'(w00$0 & r_mask);
        c00$1 = 32'((w00$1 >> 'h10) & gba_mask);
        c00$2 = 32'((w00$2 >> 'h20) & gba_mask);
        c00$3 = 32'((w00$3 >> 'h30) & gba_mask);
        c10$0 = 32'(w10$0 & r_mask);
        c10$1 = 32'((w10$1 >> 'h10) & gba_mask);
        c10$2 = 32'((w10$2 >> 'h20) & gba_mask);
        c10$3 = 32'((w10$3 >> 'h30) & gba_mask);
        c01$0 = 32'(w01$0 & r_mask);
        c01$1 = 32'((w01$1 >> 'h10) & gba_mask);
        c01$2 = 32'((w01$2 >> 'h20) & gba_mask);
        c01$3 = 32'((w01$3 >> 'h30) & gba_mask);
        c11$0 = 32'(w11$0 & r_mask);
        c11$1 = 32'((w11$1 >> 'h10) & gba_mask);
        c11$2 = 32'((w11$2 >> 'h20) & gba_mask);
        c11$3 = 32'((w11$3 >> 'h30) & gba_mask);
    end
    
endmodule // top$lanes$1$cells
module top$lanes$1$ctl(clock,valid,er,pad,base_x,base_y,face,x,y,sr,dx_neg,dx_mag,dy_neg,dy_mag,dims,coord_mask,x_t,dx_mag_t,dy_mag_t,sel_t$0,sel_t$1,sel_t$2,sel_t$3,res_beat,res_valid,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  valid;
    input wire  er;
    input wire  pad;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  sr;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [63:0] dims;
    input wire  [15:0] coord_mask;
    output reg  [15:0] x_t;
    output reg  [15:0] dx_mag_t;
    output reg  [15:0] dy_mag_t;
    output reg  [6:0] sel_t$0;
    output reg  [6:0] sel_t$1;
    output reg  [6:0] sel_t$2;
    output reg  [6:0] sel_t$3;
    output reg  res_beat;
    output reg  res_valid;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Stub signals
    reg  [15:0] nx_last$d;
    wire  [15:0] nx_last$q;
    reg  nx_last$clock;
    reg  [15:0] ny_last$d;
    wire  [15:0] ny_last$q;
    reg  ny_last$clock;
    reg  [6:0] sel_q$0$d;
    wire  [6:0] sel_q$0$q;
    reg  sel_q$0$clock;
    reg  [6:0] sel_q$1$d;
    wire  [6:0] sel_q$1$q;
    reg  sel_q$1$clock;
    reg  [6:0] sel_q$2$d;
    wire  [6:0] sel_q$2$q;
    reg  sel_q$2$clock;
    reg  [6:0] sel_q$3$d;
    wire  [6:0] sel_q$3$q;
    reg  sel_q$3$clock;
    reg  [15:0] x_q$0$d;
    wire  [15:0] x_q$0$q;
    reg  x_q$0$clock;
    reg  [15:0] x_q$1$d;
    wire  [15:0] x_q$1$q;
    reg  x_q$1$clock;
    reg  [15:0] x_q$2$d;
    wire  [15:0] x_q$2$q;
    reg  x_q$2$clock;
    reg  [15:0] x_q$3$d;
    wire  [15:0] x_q$3$q;
    reg  x_q$3$clock;
    reg  [15:0] x_q$4$d;
    wire  [15:0] x_q$4$q;
    reg  x_q$4$clock;
    reg  [15:0] x_q$5$d;
    wire  [15:0] x_q$5$q;
    reg  x_q$5$clock;
    reg  [15:0] x_q$6$d;
    wire  [15:0] x_q$6$q;
    reg  x_q$6$clock;
    reg  [15:0] x_q$7$d;
    wire  [15:0] x_q$7$q;
    reg  x_q$7$clock;
    reg  [15:0] x_q$8$d;
    wire  [15:0] x_q$8$q;
    reg  x_q$8$clock;
    reg  [15:0] x_q$9$d;
    wire  [15:0] x_q$9$q;
    reg  x_q$9$clock;
    reg  [15:0] y_q$0$d;
    wire  [15:0] y_q$0$q;
    reg  y_q$0$clock;
    reg  [15:0] y_q$1$d;
    wire  [15:0] y_q$1$q;
    reg  y_q$1$clock;
    reg  [15:0] y_q$2$d;
    wire  [15:0] y_q$2$q;
    reg  y_q$2$clock;
    reg  [15:0] y_q$3$d;
    wire  [15:0] y_q$3$q;
    reg  y_q$3$clock;
    reg  [15:0] y_q$4$d;
    wire  [15:0] y_q$4$q;
    reg  y_q$4$clock;
    reg  [15:0] y_q$5$d;
    wire  [15:0] y_q$5$q;
    reg  y_q$5$clock;
    reg  [15:0] y_q$6$d;
    wire  [15:0] y_q$6$q;
    reg  y_q$6$clock;
    reg  [15:0] y_q$7$d;
    wire  [15:0] y_q$7$q;
    reg  y_q$7$clock;
    reg  [15:0] y_q$8$d;
    wire  [15:0] y_q$8$q;
    reg  y_q$8$clock;
    reg  sr_q$0$d;
    wire  sr_q$0$q;
    reg  sr_q$0$clock;
    reg  sr_q$1$d;
    wire  sr_q$1$q;
    reg  sr_q$1$clock;
    reg  sr_q$2$d;
    wire  sr_q$2$q;
    reg  sr_q$2$clock;
    reg  sr_q$3$d;
    wire  sr_q$3$q;
    reg  sr_q$3$clock;
    reg  sr_q$4$d;
    wire  sr_q$4$q;
    reg  sr_q$4$clock;
    reg  sr_q$5$d;
    wire  sr_q$5$q;
    reg  sr_q$5$clock;
    reg  sr_q$6$d;
    wire  sr_q$6$q;
    reg  sr_q$6$clock;
    reg  sr_q$7$d;
    wire  sr_q$7$q;
    reg  sr_q$7$clock;
    reg  sr_q$8$d;
    wire  sr_q$8$q;
    reg  sr_q$8$clock;
    reg  dxn_q$0$d;
    wire  dxn_q$0$q;
    reg  dxn_q$0$clock;
    reg  dxn_q$1$d;
    wire  dxn_q$1$q;
    reg  dxn_q$1$clock;
    reg  dxn_q$2$d;
    wire  dxn_q$2$q;
    reg  dxn_q$2$clock;
    reg  dxn_q$3$d;
    wire  dxn_q$3$q;
    reg  dxn_q$3$clock;
    reg  dxn_q$4$d;
    wire  dxn_q$4$q;
    reg  dxn_q$4$clock;
    reg  dxn_q$5$d;
    wire  dxn_q$5$q;
    reg  dxn_q$5$clock;
    reg  dxn_q$6$d;
    wire  dxn_q$6$q;
    reg  dxn_q$6$clock;
    reg  dxn_q$7$d;
    wire  dxn_q$7$q;
    reg  dxn_q$7$clock;
    reg  dxn_q$8$d;
    wire  dxn_q$8$q;
    reg  dxn_q$8$clock;
    reg  [15:0] dxm_q$0$d;
    wire  [15:0] dxm_q$0$q;
    reg  dxm_q$0$clock;
    reg  [15:0] dxm_q$1$d;
    wire  [15:0] dxm_q$1$q;
    reg  dxm_q$1$clock;
    reg  [15:0] dxm_q$2$d;
    wire  [15:0] dxm_q$2$q;
    reg  dxm_q$2$clock;
    reg  [15:0] dxm_q$3$d;
    wire  [15:0] dxm_q$3$q;
    reg  dxm_q$3$clock;
    reg  [15:0] dxm_q$4$d;
    wire  [15:0] dxm_q$4$q;
    reg  dxm_q$4$clock;
    reg  [15:0] dxm_q$5$d;
    wire  [15:0] dxm_q$5$q;
    reg  dxm_q$5$clock;
    reg  [15:0] dxm_q$6$d;
    wire  [15:0] dxm_q$6$q;
    reg  dxm_q$6$clock;
    reg  [15:0] dxm_q$7$d;
    wire  [15:0] dxm_q$7$q;
    reg  dxm_q$7$clock;
    reg  [15:0] dxm_q$8$d;
    wire  [15:0] dxm_q$8$q;
    reg  dxm_q$8$clock;
    reg  [15:0] dxm_q$9$d;
    wire  [15:0] dxm_q$9$q;
    reg  dxm_q$9$clock;
    reg  dyn_q$0$d;
    wire  dyn_q$0$q;
    reg  dyn_q$0$clock;
    reg  dyn_q$1$d;
    wire  dyn_q$1$q;
    reg  dyn_q$1$clock;
    reg  dyn_q$2$d;
    wire  dyn_q$2$q;
    reg  dyn_q$2$clock;
    reg  dyn_q$3$d;
    wire  dyn_q$3$q;
    reg  dyn_q$3$clock;
    reg  dyn_q$4$d;
    wire  dyn_q$4$q;
    reg  dyn_q$4$clock;
    reg  dyn_q$5$d;
    wire  dyn_q$5$q;
    reg  dyn_q$5$clock;
    reg  dyn_q$6$d;
    wire  dyn_q$6$q;
    reg  dyn_q$6$clock;
    reg  dyn_q$7$d;
    wire  dyn_q$7$q;
    reg  dyn_q$7$clock;
    reg  dyn_q$8$d;
    wire  dyn_q$8$q;
    reg  dyn_q$8$clock;
    reg  [15:0] dym_q$0$d;
    wire  [15:0] dym_q$0$q;
    reg  dym_q$0$clock;
    reg  [15:0] dym_q$1$d;
    wire  [15:0] dym_q$1$q;
    reg  dym_q$1$clock;
    reg  [15:0] dym_q$2$d;
    wire  [15:0] dym_q$2$q;
    reg  dym_q$2$clock;
    reg  [15:0] dym_q$3$d;
    wire  [15:0] dym_q$3$q;
    reg  dym_q$3$clock;
    reg  [15:0] dym_q$4$d;
    wire  [15:0] dym_q$4$q;
    reg  dym_q$4$clock;
    reg  [15:0] dym_q$5$d;
    wire  [15:0] dym_q$5$q;
    reg  dym_q$5$clock;
    reg  [15:0] dym_q$6$d;
    wire  [15:0] dym_q$6$q;
    reg  dym_q$6$clock;
    reg  [15:0] dym_q$7$d;
    wire  [15:0] dym_q$7$q;
    reg  dym_q$7$clock;
    reg  [15:0] dym_q$8$d;
    wire  [15:0] dym_q$8$q;
    reg  dym_q$8$clock;
    reg  [15:0] dym_q$9$d;
    wire  [15:0] dym_q$9$q;
    reg  dym_q$9$clock;
    reg  v_q$0$d;
    wire  v_q$0$q;
    reg  v_q$0$clock;
    reg  v_q$1$d;
    wire  v_q$1$q;
    reg  v_q$1$clock;
    reg  v_q$2$d;
    wire  v_q$2$q;
    reg  v_q$2$clock;
    reg  v_q$3$d;
    wire  v_q$3$q;
    reg  v_q$3$clock;
    reg  v_q$4$d;
    wire  v_q$4$q;
    reg  v_q$4$clock;
    reg  v_q$5$d;
    wire  v_q$5$q;
    reg  v_q$5$clock;
    reg  v_q$6$d;
    wire  v_q$6$q;
    reg  v_q$6$clock;
    reg  v_q$7$d;
    wire  v_q$7$q;
    reg  v_q$7$clock;
    reg  v_q$8$d;
    wire  v_q$8$q;
    reg  v_q$8$clock;
    reg  v_q$9$d;
    wire  v_q$9$q;
    reg  v_q$9$clock;
    reg  v_q$10$d;
    wire  v_q$10$q;
    reg  v_q$10$clock;
    reg  v_q$11$d;
    wire  v_q$11$q;
    reg  v_q$11$clock;
    reg  v_q$12$d;
    wire  v_q$12$q;
    reg  v_q$12$clock;
    reg  v_q$13$d;
    wire  v_q$13$q;
    reg  v_q$13$clock;
    reg  v_q$14$d;
    wire  v_q$14$q;
    reg  v_q$14$clock;
    reg  v_q$15$d;
    wire  v_q$15$q;
    reg  v_q$15$clock;
    reg  v_q$16$d;
    wire  v_q$16$q;
    reg  v_q$16$clock;
    reg  v_q$17$d;
    wire  v_q$17$q;
    reg  v_q$17$clock;
    reg  v_q$18$d;
    wire  v_q$18$q;
    reg  v_q$18$clock;
    reg  v_q$19$d;
    wire  v_q$19$q;
    reg  v_q$19$clock;
    reg  v_q$20$d;
    wire  v_q$20$q;
    reg  v_q$20$clock;
    reg  er_q$0$d;
    wire  er_q$0$q;
    reg  er_q$0$clock;
    reg  er_q$1$d;
    wire  er_q$1$q;
    reg  er_q$1$clock;
    reg  er_q$2$d;
    wire  er_q$2$q;
    reg  er_q$2$clock;
    reg  er_q$3$d;
    wire  er_q$3$q;
    reg  er_q$3$clock;
    reg  er_q$4$d;
    wire  er_q$4$q;
    reg  er_q$4$clock;
    reg  er_q$5$d;
    wire  er_q$5$q;
    reg  er_q$5$clock;
    reg  er_q$6$d;
    wire  er_q$6$q;
    reg  er_q$6$clock;
    reg  er_q$7$d;
    wire  er_q$7$q;
    reg  er_q$7$clock;
    reg  er_q$8$d;
    wire  er_q$8$q;
    reg  er_q$8$clock;
    reg  er_q$9$d;
    wire  er_q$9$q;
    reg  er_q$9$clock;
    reg  er_q$10$d;
    wire  er_q$10$q;
    reg  er_q$10$clock;
    reg  er_q$11$d;
    wire  er_q$11$q;
    reg  er_q$11$clock;
    reg  er_q$12$d;
    wire  er_q$12$q;
    reg  er_q$12$clock;
    reg  er_q$13$d;
    wire  er_q$13$q;
    reg  er_q$13$clock;
    reg  er_q$14$d;
    wire  er_q$14$q;
    reg  er_q$14$clock;
    reg  er_q$15$d;
    wire  er_q$15$q;
    reg  er_q$15$clock;
    reg  er_q$16$d;
    wire  er_q$16$q;
    reg  er_q$16$clock;
    reg  er_q$17$d;
    wire  er_q$17$q;
    reg  er_q$17$clock;
    reg  er_q$18$d;
    wire  er_q$18$q;
    reg  er_q$18$clock;
    reg  er_q$19$d;
    wire  er_q$19$q;
    reg  er_q$19$clock;
    reg  er_q$20$d;
    wire  er_q$20$q;
    reg  er_q$20$clock;
    reg  pad_q$0$d;
    wire  pad_q$0$q;
    reg  pad_q$0$clock;
    reg  pad_q$1$d;
    wire  pad_q$1$q;
    reg  pad_q$1$clock;
    reg  pad_q$2$d;
    wire  pad_q$2$q;
    reg  pad_q$2$clock;
    reg  pad_q$3$d;
    wire  pad_q$3$q;
    reg  pad_q$3$clock;
    reg  pad_q$4$d;
    wire  pad_q$4$q;
    reg  pad_q$4$clock;
    reg  pad_q$5$d;
    wire  pad_q$5$q;
    reg  pad_q$5$clock;
    reg  pad_q$6$d;
    wire  pad_q$6$q;
    reg  pad_q$6$clock;
    reg  pad_q$7$d;
    wire  pad_q$7$q;
    reg  pad_q$7$clock;
    reg  pad_q$8$d;
    wire  pad_q$8$q;
    reg  pad_q$8$clock;
    reg  pad_q$9$d;
    wire  pad_q$9$q;
    reg  pad_q$9$clock;
    reg  pad_q$10$d;
    wire  pad_q$10$q;
    reg  pad_q$10$clock;
    reg  pad_q$11$d;
    wire  pad_q$11$q;
    reg  pad_q$11$clock;
    reg  pad_q$12$d;
    wire  pad_q$12$q;
    reg  pad_q$12$clock;
    reg  pad_q$13$d;
    wire  pad_q$13$q;
    reg  pad_q$13$clock;
    reg  pad_q$14$d;
    wire  pad_q$14$q;
    reg  pad_q$14$clock;
    reg  pad_q$15$d;
    wire  pad_q$15$q;
    reg  pad_q$15$clock;
    reg  pad_q$16$d;
    wire  pad_q$16$q;
    reg  pad_q$16$clock;
    reg  pad_q$17$d;
    wire  pad_q$17$q;
    reg  pad_q$17$clock;
    reg  pad_q$18$d;
    wire  pad_q$18$q;
    reg  pad_q$18$clock;
    reg  pad_q$19$d;
    wire  pad_q$19$q;
    reg  pad_q$19$clock;
    reg  pad_q$20$d;
    wire  pad_q$20$q;
    reg  pad_q$20$clock;
    reg  [15:0] bx_q$0$d;
    wire  [15:0] bx_q$0$q;
    reg  bx_q$0$clock;
    reg  [15:0] bx_q$1$d;
    wire  [15:0] bx_q$1$q;
    reg  bx_q$1$clock;
    reg  [15:0] bx_q$2$d;
    wire  [15:0] bx_q$2$q;
    reg  bx_q$2$clock;
    reg  [15:0] bx_q$3$d;
    wire  [15:0] bx_q$3$q;
    reg  bx_q$3$clock;
    reg  [15:0] bx_q$4$d;
    wire  [15:0] bx_q$4$q;
    reg  bx_q$4$clock;
    reg  [15:0] bx_q$5$d;
    wire  [15:0] bx_q$5$q;
    reg  bx_q$5$clock;
    reg  [15:0] bx_q$6$d;
    wire  [15:0] bx_q$6$q;
    reg  bx_q$6$clock;
    reg  [15:0] bx_q$7$d;
    wire  [15:0] bx_q$7$q;
    reg  bx_q$7$clock;
    reg  [15:0] bx_q$8$d;
    wire  [15:0] bx_q$8$q;
    reg  bx_q$8$clock;
    reg  [15:0] bx_q$9$d;
    wire  [15:0] bx_q$9$q;
    reg  bx_q$9$clock;
    reg  [15:0] bx_q$10$d;
    wire  [15:0] bx_q$10$q;
    reg  bx_q$10$clock;
    reg  [15:0] bx_q$11$d;
    wire  [15:0] bx_q$11$q;
    reg  bx_q$11$clock;
    reg  [15:0] bx_q$12$d;
    wire  [15:0] bx_q$12$q;
    reg  bx_q$12$clock;
    reg  [15:0] bx_q$13$d;
    wire  [15:0] bx_q$13$q;
    reg  bx_q$13$clock;
    reg  [15:0] bx_q$14$d;
    wire  [15:0] bx_q$14$q;
    reg  bx_q$14$clock;
    reg  [15:0] bx_q$15$d;
    wire  [15:0] bx_q$15$q;
    reg  bx_q$15$clock;
    reg  [15:0] bx_q$16$d;
    wire  [15:0] bx_q$16$q;
    reg  bx_q$16$clock;
    reg  [15:0] bx_q$17$d;
    wire  [15:0] bx_q$17$q;
    reg  bx_q$17$clock;
    reg  [15:0] bx_q$18$d;
    wire  [15:0] bx_q$18$q;
    reg  bx_q$18$clock;
    reg  [15:0] bx_q$19$d;
    wire  [15:0] bx_q$19$q;
    reg  bx_q$19$clock;
    reg  [15:0] bx_q$20$d;
    wire  [15:0] bx_q$20$q;
    reg  bx_q$20$clock;
    reg  [15:0] by_q$0$d;
    wire  [15:0] by_q$0$q;
    reg  by_q$0$clock;
    reg  [15:0] by_q$1$d;
    wire  [15:0] by_q$1$q;
    reg  by_q$1$clock;
    reg  [15:0] by_q$2$d;
    wire  [15:0] by_q$2$q;
    reg  by_q$2$clock;
    reg  [15:0] by_q$3$d;
    wire  [15:0] by_q$3$q;
    reg  by_q$3$clock;
    reg  [15:0] by_q$4$d;
    wire  [15:0] by_q$4$q;
    reg  by_q$4$clock;
    reg  [15:0] by_q$5$d;
    wire  [15:0] by_q$5$q;
    reg  by_q$5$clock;
    reg  [15:0] by_q$6$d;
    wire  [15:0] by_q$6$q;
    reg  by_q$6$clock;
    reg  [15:0] by_q$7$d;
    wire  [15:0] by_q$7$q;
    reg  by_q$7$clock;
    reg  [15:0] by_q$8$d;
    wire  [15:0] by_q$8$q;
    reg  by_q$8$clock;
    reg  [15:0] by_q$9$d;
    wire  [15:0] by_q$9$q;
    reg  by_q$9$clock;
    reg  [15:0] by_q$10$d;
    wire  [15:0] by_q$10$q;
    reg  by_q$10$clock;
    reg  [15:0] by_q$11$d;
    wire  [15:0] by_q$11$q;
    reg  by_q$11$clock;
    reg  [15:0] by_q$12$d;
    wire  [15:0] by_q$12$q;
    reg  by_q$12$clock;
    reg  [15:0] by_q$13$d;
    wire  [15:0] by_q$13$q;
    reg  by_q$13$clock;
    reg  [15:0] by_q$14$d;
    wire  [15:0] by_q$14$q;
    reg  by_q$14$clock;
    reg  [15:0] by_q$15$d;
    wire  [15:0] by_q$15$q;
    reg  by_q$15$clock;
    reg  [15:0] by_q$16$d;
    wire  [15:0] by_q$16$q;
    reg  by_q$16$clock;
    reg  [15:0] by_q$17$d;
    wire  [15:0] by_q$17$q;
    reg  by_q$17$clock;
    reg  [15:0] by_q$18$d;
    wire  [15:0] by_q$18$q;
    reg  by_q$18$clock;
    reg  [15:0] by_q$19$d;
    wire  [15:0] by_q$19$q;
    reg  by_q$19$clock;
    reg  [15:0] by_q$20$d;
    wire  [15:0] by_q$20$q;
    reg  by_q$20$clock;
    reg  [2:0] face_q$0$d;
    wire  [2:0] face_q$0$q;
    reg  face_q$0$clock;
    reg  [2:0] face_q$1$d;
    wire  [2:0] face_q$1$q;
    reg  face_q$1$clock;
    reg  [2:0] face_q$2$d;
    wire  [2:0] face_q$2$q;
    reg  face_q$2$clock;
    reg  [2:0] face_q$3$d;
    wire  [2:0] face_q$3$q;
    reg  face_q$3$clock;
    reg  [2:0] face_q$4$d;
    wire  [2:0] face_q$4$q;
    reg  face_q$4$clock;
    reg  [2:0] face_q$5$d;
    wire  [2:0] face_q$5$q;
    reg  face_q$5$clock;
    reg  [2:0] face_q$6$d;
    wire  [2:0] face_q$6$q;
    reg  face_q$6$clock;
    reg  [2:0] face_q$7$d;
    wire  [2:0] face_q$7$q;
    reg  face_q$7$clock;
    reg  [2:0] face_q$8$d;
    wire  [2:0] face_q$8$q;
    reg  face_q$8$clock;
    reg  [2:0] face_q$9$d;
    wire  [2:0] face_q$9$q;
    reg  face_q$9$clock;
    reg  [2:0] face_q$10$d;
    wire  [2:0] face_q$10$q;
    reg  face_q$10$clock;
    reg  [2:0] face_q$11$d;
    wire  [2:0] face_q$11$q;
    reg  face_q$11$clock;
    reg  [2:0] face_q$12$d;
    wire  [2:0] face_q$12$q;
    reg  face_q$12$clock;
    reg  [2:0] face_q$13$d;
    wire  [2:0] face_q$13$q;
    reg  face_q$13$clock;
    reg  [2:0] face_q$14$d;
    wire  [2:0] face_q$14$q;
    reg  face_q$14$clock;
    reg  [2:0] face_q$15$d;
    wire  [2:0] face_q$15$q;
    reg  face_q$15$clock;
    reg  [2:0] face_q$16$d;
    wire  [2:0] face_q$16$q;
    reg  face_q$16$clock;
    reg  [2:0] face_q$17$d;
    wire  [2:0] face_q$17$q;
    reg  face_q$17$clock;
    reg  [2:0] face_q$18$d;
    wire  [2:0] face_q$18$q;
    reg  face_q$18$clock;
    reg  [2:0] face_q$19$d;
    wire  [2:0] face_q$19$q;
    reg  face_q$19$clock;
    reg  [2:0] face_q$20$d;
    wire  [2:0] face_q$20$q;
    reg  face_q$20$clock;
    
    // Local signals
    reg  x_out;
    reg  y_out;
    reg  dx_nz;
    reg  dy_nz;
    reg  [6:0] sel;
    
    // Sub module instances
    top$lanes$1$ctl$nx_last nx_last(
        .d(nx_last$d),
        .q(nx_last$q),
        .clock(nx_last$clock)
    );
    top$lanes$1$ctl$ny_last ny_last(
        .d(ny_last$d),
        .q(ny_last$q),
        .clock(ny_last$clock)
    );
    top$lanes$1$ctl$sel_q$0 sel_q$0(
        .d(sel_q$0$d),
        .q(sel_q$0$q),
        .clock(sel_q$0$clock)
    );
    top$lanes$1$ctl$sel_q$1 sel_q$1(
        .d(sel_q$1$d),
        .q(sel_q$1$q),
        .clock(sel_q$1$clock)
    );
    top$lanes$1$ctl$sel_q$2 sel_q$2(
        .d(sel_q$2$d),
        .q(sel_q$2$q),
        .clock(sel_q$2$clock)
    );
    top$lanes$1$ctl$sel_q$3 sel_q$3(
        .d(sel_q$3$d),
        .q(sel_q$3$q),
        .clock(sel_q$3$clock)
    );
    top$lanes$1$ctl$x_q$0 x_q$0(
        .d(x_q$0$d),
        .q(x_q$0$q),
        .clock(x_q$0$clock)
    );
    top$lanes$1$ctl$x_q$1 x_q$1(
        .d(x_q$1$d),
        .q(x_q$1$q),
        .clock(x_q$1$clock)
    );
    top$lanes$1$ctl$x_q$2 x_q$2(
        .d(x_q$2$d),
        .q(x_q$2$q),
        .clock(x_q$2$clock)
    );
    top$lanes$1$ctl$x_q$3 x_q$3(
        .d(x_q$3$d),
        .q(x_q$3$q),
        .clock(x_q$3$clock)
    );
    top$lanes$1$ctl$x_q$4 x_q$4(
        .d(x_q$4$d),
        .q(x_q$4$q),
        .clock(x_q$4$clock)
    );
    top$lanes$1$ctl$x_q$5 x_q$5(
        .d(x_q$5$d),
        .q(x_q$5$q),
        .clock(x_q$5$clock)
    );
    top$lanes$1$ctl$x_q$6 x_q$6(
        .d(x_q$6$d),
        .q(x_q$6$q),
        .clock(x_q$6$clock)
    );
    top$lanes$1$ctl$x_q$7 x_q$7(
        .d(x_q$7$d),
        .q(x_q$7$q),
        .clock(x_q$7$clock)
    );
    top$lanes$1$ctl$x_q$8 x_q$8(
        .d(x_q$8$d),
        .q(x_q$8$q),
        .clock(x_q$8$clock)
    );
    top$lanes$1$ctl$x_q$9 x_q$9(
        .d(x_q$9$d),
        .q(x_q$9$q),
        .clock(x_q$9$clock)
    );
    top$lanes$1$ctl$y_q$0 y_q$0(
        .d(y_q$0$d),
        .q(y_q$0$q),
        .clock(y_q$0$clock)
    );
    top$lanes$1$ctl$y_q$1 y_q$1(
        .d(y_q$1$d),
        .q(y_q$1$q),
        .clock(y_q$1$clock)
    );
    top$lanes$1$ctl$y_q$2 y_q$2(
        .d(y_q$2$d),
        .q(y_q$2$q),
        .clock(y_q$2$clock)
    );
    top$lanes$1$ctl$y_q$3 y_q$3(
        .d(y_q$3$d),
        .q(y_q$3$q),
        .clock(y_q$3$clock)
    );
    top$lanes$1$ctl$y_q$4 y_q$4(
        .d(y_q$4$d),
        .q(y_q$4$q),
        .clock(y_q$4$clock)
    );
    top$lanes$1$ctl$y_q$5 y_q$5(
        .d(y_q$5$d),
        .q(y_q$5$q),
        .clock(y_q$5$clock)
    );
    top$lanes$1$ctl$y_q$6 y_q$6(
        .d(y_q$6$d),
        .q(y_q$6$q),
        .clock(y_q$6$clock)
    );
    top$lanes$1$ctl$y_q$7 y_q$7(
        .d(y_q$7$d),
        .q(y_q$7$q),
        .clock(y_q$7$clock)
    );
    top$lanes$1$ctl$y_q$8 y_q$8(
        .d(y_q$8$d),
        .q(y_q$8$q),
        .clock(y_q$8$clock)
    );
    top$lanes$1$ctl$sr_q$0 sr_q$0(
        .d(sr_q$0$d),
        .q(sr_q$0$q),
        .clock(sr_q$0$clock)
    );
    top$lanes$1$ctl$sr_q$1 sr_q$1(
        .d(sr_q$1$d),
        .q(sr_q$1$q),
        .clock(sr_q$1$clock)
    );
    top$lanes$1$ctl$sr_q$2 sr_q$2(
        .d(sr_q$2$d),
        .q(sr_q$2$q),
        .clock(sr_q$2$clock)
    );
    top$lanes$1$ctl$sr_q$3 sr_q$3(
        .d(sr_q$3$d),
        .q(sr_q$3$q),
        .clock(sr_q$3$clock)
    );
    top$lanes$1$ctl$sr_q$4 sr_q$4(
        .d(sr_q$4$d),
        .q(sr_q$4$q),
        .clock(sr_q$4$clock)
    );
    top$lanes$1$ctl$sr_q$5 sr_q$5(
        .d(sr_q$5$d),
        .q(sr_q$5$q),
        .clock(sr_q$5$clock)
    );
    top$lanes$1$ctl$sr_q$6 sr_q$6(
        .d(sr_q$6$d),
        .q(sr_q$6$q),
        .clock(sr_q$6$clock)
    );
    top$lanes$1$ctl$sr_q$7 sr_q$7(
        .d(sr_q$7$d),
        .q(sr_q$7$q),
        .clock(sr_q$7$clock)
    );
    top$lanes$1$ctl$sr_q$8 sr_q$8(
        .d(sr_q$8$d),
        .q(sr_q$8$q),
        .clock(sr_q$8$clock)
    );
    top$lanes$1$ctl$dxn_q$0 dxn_q$0(
        .d(dxn_q$0$d),
        .q(dxn_q$0$q),
        .clock(dxn_q$0$clock)
    );
    top$lanes$1$ctl$dxn_q$1 dxn_q$1(
        .d(dxn_q$1$d),
        .q(dxn_q$1$q),
        .clock(dxn_q$1$clock)
    );
    top$lanes$1$ctl$dxn_q$2 dxn_q$2(
        .d(dxn_q$2$d),
        .q(dxn_q$2$q),
        .clock(dxn_q$2$clock)
    );
    top$lanes$1$ctl$dxn_q$3 dxn_q$3(
        .d(dxn_q$3$d),
        .q(dxn_q$3$q),
        .clock(dxn_q$3$clock)
    );
    top$lanes$1$ctl$dxn_q$4 dxn_q$4(
        .d(dxn_q$4$d),
        .q(dxn_q$4$q),
        .clock(dxn_q$4$clock)
    );
    top$lanes$1$ctl$dxn_q$5 dxn_q$5(
        .d(dxn_q$5$d),
        .q(dxn_q$5$q),
        .clock(dxn_q$5$clock)
    );
    top$lanes$1$ctl$dxn_q$6 dxn_q$6(
        .d(dxn_q$6$d),
        .q(dxn_q$6$q),
        .clock(dxn_q$6$clock)
    );
    top$lanes$1$ctl$dxn_q$7 dxn_q$7(
        .d(dxn_q$7$d),
        .q(dxn_q$7$q),
        .clock(dxn_q$7$clock)
    );
    top$lanes$1$ctl$dxn_q$8 dxn_q$8(
        .d(dxn_q$8$d),
        .q(dxn_q$8$q),
        .clock(dxn_q$8$clock)
    );
    top$lanes$1$ctl$dxm_q$0 dxm_q$0(
        .d(dxm_q$0$d),
        .q(dxm_q$0$q),
        .clock(dxm_q$0$clock)
    );
    top$lanes$1$ctl$dxm_q$1 dxm_q$1(
        .d(dxm_q$1$d),
        .q(dxm_q$1$q),
        .clock(dxm_q$1$clock)
    );
    top$lanes$1$ctl$dxm_q$2 dxm_q$2(
        .d(dxm_q$2$d),
        .q(dxm_q$2$q),
        .clock(dxm_q$2$clock)
    );
    top$lanes$1$ctl$dxm_q$3 dxm_q$3(
        .d(dxm_q$3$d),
        .q(dxm_q$3$q),
        .clock(dxm_q$3$clock)
    );
    top$lanes$1$ctl$dxm_q$4 dxm_q$4(
        .d(dxm_q$4$d),
        .q(dxm_q$4$q),
        .clock(dxm_q$4$clock)
    );
    top$lanes$1$ctl$dxm_q$5 dxm_q$5(
        .d(dxm_q$5$d),
        .q(dxm_q$5$q),
        .clock(dxm_q$5$clock)
    );
    top$lanes$1$ctl$dxm_q$6 dxm_q$6(
        .d(dxm_q$6$d),
        .q(dxm_q$6$q),
        .clock(dxm_q$6$clock)
    );
    top$lanes$1$ctl$dxm_q$7 dxm_q$7(
        .d(dxm_q$7$d),
        .q(dxm_q$7$q),
        .clock(dxm_q$7$clock)
    );
    top$lanes$1$ctl$dxm_q$8 dxm_q$8(
        .d(dxm_q$8$d),
        .q(dxm_q$8$q),
        .clock(dxm_q$8$clock)
    );
    top$lanes$1$ctl$dxm_q$9 dxm_q$9(
        .d(dxm_q$9$d),
        .q(dxm_q$9$q),
        .clock(dxm_q$9$clock)
    );
    top$lanes$1$ctl$dyn_q$0 dyn_q$0(
        .d(dyn_q$0$d),
        .q(dyn_q$0$q),
        .clock(dyn_q$0$clock)
    );
    top$lanes$1$ctl$dyn_q$1 dyn_q$1(
        .d(dyn_q$1$d),
        .q(dyn_q$1$q),
        .clock(dyn_q$1$clock)
    );
    top$lanes$1$ctl$dyn_q$2 dyn_q$2(
        .d(dyn_q$2$d),
        .q(dyn_q$2$q),
        .clock(dyn_q$2$clock)
    );
    top$lanes$1$ctl$dyn_q$3 dyn_q$3(
        .d(dyn_q$3$d),
        .q(dyn_q$3$q),
        .clock(dyn_q$3$clock)
    );
    top$lanes$1$ctl$dyn_q$4 dyn_q$4(
        .d(dyn_q$4$d),
        .q(dyn_q$4$q),
        .clock(dyn_q$4$clock)
    );
    top$lanes$1$ctl$dyn_q$5 dyn_q$5(
        .d(dyn_q$5$d),
        .q(dyn_q$5$q),
        .clock(dyn_q$5$clock)
    );
    top$lanes$1$ctl$dyn_q$6 dyn_q$6(
        .d(dyn_q$6$d),
        .q(dyn_q$6$q),
        .clock(dyn_q$6$clock)
    );
    top$lanes$1$ctl$dyn_q$7 dyn_q$7(
        .d(dyn_q$7$d),
        .q(dyn_q$7$q),
        .clock(dyn_q$7$clock)
    );
    top$lanes$1$ctl$dyn_q$8 dyn_q$8(
        .d(dyn_q$8$d),
        .q(dyn_q$8$q),
        .clock(dyn_q$8$clock)
    );
    top$lanes$1$ctl$dym_q$0 dym_q$0(
        .d(dym_q$0$d),
        .q(dym_q$0$q),
        .clock(dym_q$0$clock)
    );
    top$lanes$1$ctl$dym_q$1 dym_q$1(
        .d(dym_q$1$d),
        .q(dym_q$1$q),
        .clock(dym_q$1$clock)
    );
    top$lanes$1$ctl$dym_q$2 dym_q$2(
        .d(dym_q$2$d),
        .q(dym_q$2$q),
        .clock(dym_q$2$clock)
    );
    top$lanes$1$ctl$dym_q$3 dym_q$3(
        .d(dym_q$3$d),
        .q(dym_q$3$q),
        .clock(dym_q$3$clock)
    );
    top$lanes$1$ctl$dym_q$4 dym_q$4(
        .d(dym_q$4$d),
        .q(dym_q$4$q),
        .clock(dym_q$4$clock)
    );
    top$lanes$1$ctl$dym_q$5 dym_q$5(
        .d(dym_q$5$d),
        .q(dym_q$5$q),
        .clock(dym_q$5$clock)
    );
    top$lanes$1$ctl$dym_q$6 dym_q$6(
        .d(dym_q$6$d),
        .q(dym_q$6$q),
        .clock(dym_q$6$clock)
    );
    top$lanes$1$ctl$dym_q$7 dym_q$7(
        .d(dym_q$7$d),
        .q(dym_q$7$q),
        .clock(dym_q$7$clock)
    );
    top$lanes$1$ctl$dym_q$8 dym_q$8(
        .d(dym_q$8$d),
        .q(dym_q$8$q),
        .clock(dym_q$8$clock)
    );
    top$lanes$1$ctl$dym_q$9 dym_q$9(
        .d(dym_q$9$d),
        .q(dym_q$9$q),
        .clock(dym_q$9$clock)
    );
    top$lanes$1$ctl$v_q$0 v_q$0(
        .d(v_q$0$d),
        .q(v_q$0$q),
        .clock(v_q$0$clock)
    );
    top$lanes$1$ctl$v_q$1 v_q$1(
        .d(v_q$1$d),
        .q(v_q$1$q),
        .clock(v_q$1$clock)
    );
    top$lanes$1$ctl$v_q$2 v_q$2(
        .d(v_q$2$d),
        .q(v_q$2$q),
        .clock(v_q$2$clock)
    );
    top$lanes$1$ctl$v_q$3 v_q$3(
        .d(v_q$3$d),
        .q(v_q$3$q),
        .clock(v_q$3$clock)
    );
    top$lanes$1$ctl$v_q$4 v_q$4(
        .d(v_q$4$d),
        .q(v_q$4$q),
        .clock(v_q$4$clock)
    );
    top$lanes$1$ctl$v_q$5 v_q$5(
        .d(v_q$5$d),
        .q(v_q$5$q),
        .clock(v_q$5$clock)
    );
    top$lanes$1$ctl$v_q$6 v_q$6(
        .d(v_q$6$d),
        .q(v_q$6$q),
        .clock(v_q$6$clock)
    );
    top$lanes$1$ctl$v_q$7 v_q$7(
        .d(v_q$7$d),
        .q(v_q$7$q),
        .clock(v_q$7$clock)
    );
    top$lanes$1$ctl$v_q$8 v_q$8(
        .d(v_q$8$d),
        .q(v_q$8$q),
        .clock(v_q$8$clock)
    );
    top$lanes$1$ctl$v_q$9 v_q$9(
        .d(v_q$9$d),
        .q(v_q$9$q),
        .clock(v_q$9$clock)
    );
    top$lanes$1$ctl$v_q$10 v_q$10(
        .d(v_q$10$d),
        .q(v_q$10$q),
        .clock(v_q$10$clock)
    );
    top$lanes$1$ctl$v_q$11 v_q$11(
        .d(v_q$11$d),
        .q(v_q$11$q),
        .clock(v_q$11$clock)
    );
    top$lanes$1$ctl$v_q$12 v_q$12(
        .d(v_q$12$d),
        .q(v_q$12$q),
        .clock(v_q$12$clock)
    );
    top$lanes$1$ctl$v_q$13 v_q$13(
        .d(v_q$13$d),
        .q(v_q$13$q),
        .clock(v_q$13$clock)
    );
    top$lanes$1$ctl$v_q$14 v_q$14(
        .d(v_q$14$d),
        .q(v_q$14$q),
        .clock(v_q$14$clock)
    );
    top$lanes$1$ctl$v_q$15 v_q$15(
        .d(v_q$15$d),
        .q(v_q$15$q),
        .clock(v_q$15$clock)
    );
    top$lanes$1$ctl$v_q$16 v_q$16(
        .d(v_q$16$d),
        .q(v_q$16$q),
        .clock(v_q$16$clock)
    );
    top$lanes$1$ctl$v_q$17 v_q$17(
        .d(v_q$17$d),
        .q(v_q$17$q),
        .clock(v_q$17$clock)
    );
    top$lanes$1$ctl$v_q$18 v_q$18(
        .d(v_q$18$d),
        .q(v_q$18$q),
        .clock(v_q$18$clock)
    );
    top$lanes$1$ctl$v_q$19 v_q$19(
        .d(v_q$19$d),
        .q(v_q$19$q),
        .clock(v_q$19$clock)
    );
    top$lanes$1$ctl$v_q$20 v_q$20(
        .d(v_q$20$d),
        .q(v_q$20$q),
        .clock(v_q$20$clock)
    );
    top$lanes$1$ctl$er_q$0 er_q$0(
        .d(er_q$0$d),
        .q(er_q$0$q),
        .clock(er_q$0$clock)
    );
    top$lanes$1$ctl$er_q$1 er_q$1(
        .d(er_q$1$d),
        .q(er_q$1$q),
        .clock(er_q$1$clock)
    );
    top$lanes$1$ctl$er_q$2 er_q$2(
        .d(er_q$2$d),
        .q(er_q$2$q),
        .clock(er_q$2$clock)
    );
    top$lanes$1$ctl$er_q$3 er_q$3(
        .d(er_q$3$d),
        .q(er_q$3$q),
        .clock(er_q$3$clock)
    );
    top$lanes$1$ctl$er_q$4 er_q$4(
        .d(er_q$4$d),
        .q(er_q$4$q),
        .clock(er_q$4$clock)
    );
    top$lanes$1$ctl$er_q$5 er_q$5(
        .d(er_q$5$d),
        .q(er_q$5$q),
        .clock(er_q$5$clock)
    );
    top$lanes$1$ctl$er_q$6 er_q$6(
        .d(er_q$6$d),
        .q(er_q$6$q),
        .clock(er_q$6$clock)
    );
    top$lanes$1$ctl$er_q$7 er_q$7(
        .d(er_q$7$d),
        .q(er_q$7$q),
        .clock(er_q$7$clock)
    );
    top$lanes$1$ctl$er_q$8 er_q$8(
        .d(er_q$8$d),
        .q(er_q$8$q),
        .clock(er_q$8$clock)
    );
    top$lanes$1$ctl$er_q$9 er_q$9(
        .d(er_q$9$d),
        .q(er_q$9$q),
        .clock(er_q$9$clock)
    );
    top$lanes$1$ctl$er_q$10 er_q$10(
        .d(er_q$10$d),
        .q(er_q$10$q),
        .clock(er_q$10$clock)
    );
    top$lanes$1$ctl$er_q$11 er_q$11(
        .d(er_q$11$d),
        .q(er_q$11$q),
        .clock(er_q$11$clock)
    );
    top$lanes$1$ctl$er_q$12 er_q$12(
        .d(er_q$12$d),
        .q(er_q$12$q),
        .clock(er_q$12$clock)
    );
    top$lanes$1$ctl$er_q$13 er_q$13(
        .d(er_q$13$d),
        .q(er_q$13$q),
        .clock(er_q$13$clock)
    );
    top$lanes$1$ctl$er_q$14 er_q$14(
        .d(er_q$14$d),
        .q(er_q$14$q),
        .clock(er_q$14$clock)
    );
    top$lanes$1$ctl$er_q$15 er_q$15(
        .d(er_q$15$d),
        .q(er_q$15$q),
        .clock(er_q$15$clock)
    );
    top$lanes$1$ctl$er_q$16 er_q$16(
        .d(er_q$16$d),
        .q(er_q$16$q),
        .clock(er_q$16$clock)
    );
    top$lanes$1$ctl$er_q$17 er_q$17(
        .d(er_q$17$d),
        .q(er_q$17$q),
        .clock(er_q$17$clock)
    );
    top$lanes$1$ctl$er_q$18 er_q$18(
        .d(er_q$18$d),
        .q(er_q$18$q),
        .clock(er_q$18$clock)
    );
    top$lanes$1$ctl$er_q$19 er_q$19(
        .d(er_q$19$d),
        .q(er_q$19$q),
        .clock(er_q$19$clock)
    );
    top$lanes$1$ctl$er_q$20 er_q$20(
        .d(er_q$20$d),
        .q(er_q$20$q),
        .clock(er_q$20$clock)
    );
    top$lanes$1$ctl$pad_q$0 pad_q$0(
        .d(pad_q$0$d),
        .q(pad_q$0$q),
        .clock(pad_q$0$clock)
    );
    top$lanes$1$ctl$pad_q$1 pad_q$1(
        .d(pad_q$1$d),
        .q(pad_q$1$q),
        .clock(pad_q$1$clock)
    );
    top$lanes$1$ctl$pad_q$2 pad_q$2(
        .d(pad_q$2$d),
        .q(pad_q$2$q),
        .clock(pad_q$2$clock)
    );
    top$lanes$1$ctl$pad_q$3 pad_q$3(
        .d(pad_q$3$d),
        .q(pad_q$3$q),
        .clock(pad_q$3$clock)
    );
    top$lanes$1$ctl$pad_q$4 pad_q$4(
        .d(pad_q$4$d),
        .q(pad_q$4$q),
        .clock(pad_q$4$clock)
    );
    top$lanes$1$ctl$pad_q$5 pad_q$5(
        .d(pad_q$5$d),
        .q(pad_q$5$q),
        .clock(pad_q$5$clock)
    );
    top$lanes$1$ctl$pad_q$6 pad_q$6(
        .d(pad_q$6$d),
        .q(pad_q$6$q),
        .clock(pad_q$6$clock)
    );
    top$lanes$1$ctl$pad_q$7 pad_q$7(
        .d(pad_q$7$d),
        .q(pad_q$7$q),
        .clock(pad_q$7$clock)
    );
    top$lanes$1$ctl$pad_q$8 pad_q$8(
        .d(pad_q$8$d),
        .q(pad_q$8$q),
        .clock(pad_q$8$clock)
    );
    top$lanes$1$ctl$pad_q$9 pad_q$9(
        .d(pad_q$9$d),
        .q(pad_q$9$q),
        .clock(pad_q$9$clock)
    );
    top$lanes$1$ctl$pad_q$10 pad_q$10(
        .d(pad_q$10$d),
        .q(pad_q$10$q),
        .clock(pad_q$10$clock)
    );
    top$lanes$1$ctl$pad_q$11 pad_q$11(
        .d(pad_q$11$d),
        .q(pad_q$11$q),
        .clock(pad_q$11$clock)
    );
    top$lanes$1$ctl$pad_q$12 pad_q$12(
        .d(pad_q$12$d),
        .q(pad_q$12$q),
        .clock(pad_q$12$clock)
    );
    top$lanes$1$ctl$pad_q$13 pad_q$13(
        .d(pad_q$13$d),
        .q(pad_q$13$q),
        .clock(pad_q$13$clock)
    );
    top$lanes$1$ctl$pad_q$14 pad_q$14(
        .d(pad_q$14$d),
        .q(pad_q$14$q),
        .clock(pad_q$14$clock)
    );
    top$lanes$1$ctl$pad_q$15 pad_q$15(
        .d(pad_q$15$d),
        .q(pad_q$15$q),
        .clock(pad_q$15$clock)
    );
    top$lanes$1$ctl$pad_q$16 pad_q$16(
        .d(pad_q$16$d),
        .q(pad_q$16$q),
        .clock(pad_q$16$clock)
    );
    top$lanes$1$ctl$pad_q$17 pad_q$17(
        .d(pad_q$17$d),
        .q(pad_q$17$q),
        .clock(pad_q$17$clock)
    );
    top$lanes$1$ctl$pad_q$18 pad_q$18(
        .d(pad_q$18$d),
        .q(pad_q$18$q),
        .clock(pad_q$18$clock)
    );
    top$lanes$1$ctl$pad_q$19 pad_q$19(
        .d(pad_q$19$d),
        .q(pad_q$19$q),
        .clock(pad_q$19$clock)
    );
    top$lanes$1$ctl$pad_q$20 pad_q$20(
        .d(pad_q$20$d),
        .q(pad_q$20$q),
        .clock(pad_q$20$clock)
    );
    top$lanes$1$ctl$bx_q$0 bx_q$0(
        .d(bx_q$0$d),
        .q(bx_q$0$q),
        .clock(bx_q$0$clock)
    );
    top$lanes$1$ctl$bx_q$1 bx_q$1(
        .d(bx_q$1$d),
        .q(bx_q$1$q),
        .clock(bx_q$1$clock)
    );
    top$lanes$1$ctl$bx_q$2 bx_q$2(
        .d(bx_q$2$d),
        .q(bx_q$2$q),
        .clock(bx_q$2$clock)
    );
    top$lanes$1$ctl$bx_q$3 bx_q$3(
        .d(bx_q$3$d),
        .q(bx_q$3$q),
        .clock(bx_q$3$clock)
    );
    top$lanes$1$ctl$bx_q$4 bx_q$4(
        .d(bx_q$4$d),
        .q(bx_q$4$q),
        .clock(bx_q$4$clock)
    );
    top$lanes$1$ctl$bx_q$5 bx_q$5(
        .d(bx_q$5$d),
        .q(bx_q$5$q),
        .clock(bx_q$5$clock)
    );
    top$lanes$1$ctl$bx_q$6 bx_q$6(
        .d(bx_q$6$d),
        .q(bx_q$6$q),
        .clock(bx_q$6$clock)
    );
    top$lanes$1$ctl$bx_q$7 bx_q$7(
        .d(bx_q$7$d),
        .q(bx_q$7$q),
        .clock(bx_q$7$clock)
    );
    top$lanes$1$ctl$bx_q$8 bx_q$8(
        .d(bx_q$8$d),
        .q(bx_q$8$q),
        .clock(bx_q$8$clock)
    );
    top$lanes$1$ctl$bx_q$9 bx_q$9(
        .d(bx_q$9$d),
        .q(bx_q$9$q),
        .clock(bx_q$9$clock)
    );
    top$lanes$1$ctl$bx_q$10 bx_q$10(
        .d(bx_q$10$d),
        .q(bx_q$10$q),
        .clock(bx_q$10$clock)
    );
    top$lanes$1$ctl$bx_q$11 bx_q$11(
        .d(bx_q$11$d),
        .q(bx_q$11$q),
        .clock(bx_q$11$clock)
    );
    top$lanes$1$ctl$bx_q$12 bx_q$12(
        .d(bx_q$12$d),
        .q(bx_q$12$q),
        .clock(bx_q$12$clock)
    );
    top$lanes$1$ctl$bx_q$13 bx_q$13(
        .d(bx_q$13$d),
        .q(bx_q$13$q),
        .clock(bx_q$13$clock)
    );
    top$lanes$1$ctl$bx_q$14 bx_q$14(
        .d(bx_q$14$d),
        .q(bx_q$14$q),
        .clock(bx_q$14$clock)
    );
    top$lanes$1$ctl$bx_q$15 bx_q$15(
        .d(bx_q$15$d),
        .q(bx_q$15$q),
        .clock(bx_q$15$clock)
    );
    top$lanes$1$ctl$bx_q$16 bx_q$16(
        .d(bx_q$16$d),
        .q(bx_q$16$q),
        .clock(bx_q$16$clock)
    );
    top$lanes$1$ctl$bx_q$17 bx_q$17(
        .d(bx_q$17$d),
        .q(bx_q$17$q),
        .clock(bx_q$17$clock)
    );
    top$lanes$1$ctl$bx_q$18 bx_q$18(
        .d(bx_q$18$d),
        .q(bx_q$18$q),
        .clock(bx_q$18$clock)
    );
    top$lanes$1$ctl$bx_q$19 bx_q$19(
        .d(bx_q$19$d),
        .q(bx_q$19$q),
        .clock(bx_q$19$clock)
    );
    top$lanes$1$ctl$bx_q$20 bx_q$20(
        .d(bx_q$20$d),
        .q(bx_q$20$q),
        .clock(bx_q$20$clock)
    );
    top$lanes$1$ctl$by_q$0 by_q$0(
        .d(by_q$0$d),
        .q(by_q$0$q),
        .clock(by_q$0$clock)
    );
    top$lanes$1$ctl$by_q$1 by_q$1(
        .d(by_q$1$d),
        .q(by_q$1$q),
        .clock(by_q$1$clock)
    );
    top$lanes$1$ctl$by_q$2 by_q$2(
        .d(by_q$2$d),
        .q(by_q$2$q),
        .clock(by_q$2$clock)
    );
    top$lanes$1$ctl$by_q$3 by_q$3(
        .d(by_q$3$d),
        .q(by_q$3$q),
        .clock(by_q$3$clock)
    );
    top$lanes$1$ctl$by_q$4 by_q$4(
        .d(by_q$4$d),
        .q(by_q$4$q),
        .clock(by_q$4$clock)
    );
    top$lanes$1$ctl$by_q$5 by_q$5(
        .d(by_q$5$d),
        .q(by_q$5$q),
        .clock(by_q$5$clock)
    );
    top$lanes$1$ctl$by_q$6 by_q$6(
        .d(by_q$6$d),
        .q(by_q$6$q),
        .clock(by_q$6$clock)
    );
    top$lanes$1$ctl$by_q$7 by_q$7(
        .d(by_q$7$d),
        .q(by_q$7$q),
        .clock(by_q$7$clock)
    );
    top$lanes$1$ctl$by_q$8 by_q$8(
        .d(by_q$8$d),
        .q(by_q$8$q),
        .clock(by_q$8$clock)
    );
    top$lanes$1$ctl$by_q$9 by_q$9(
        .d(by_q$9$d),
        .q(by_q$9$q),
        .clock(by_q$9$clock)
    );
    top$lanes$1$ctl$by_q$10 by_q$10(
        .d(by_q$10$d),
        .q(by_q$10$q),
        .clock(by_q$10$clock)
    );
    top$lanes$1$ctl$by_q$11 by_q$11(
        .d(by_q$11$d),
        .q(by_q$11$q),
        .clock(by_q$11$clock)
    );
    top$lanes$1$ctl$by_q$12 by_q$12(
        .d(by_q$12$d),
        .q(by_q$12$q),
        .clock(by_q$12$clock)
    );
    top$lanes$1$ctl$by_q$13 by_q$13(
        .d(by_q$13$d),
        .q(by_q$13$q),
        .clock(by_q$13$clock)
    );
    top$lanes$1$ctl$by_q$14 by_q$14(
        .d(by_q$14$d),
        .q(by_q$14$q),
        .clock(by_q$14$clock)
    );
    top$lanes$1$ctl$by_q$15 by_q$15(
        .d(by_q$15$d),
        .q(by_q$15$q),
        .clock(by_q$15$clock)
    );
    top$lanes$1$ctl$by_q$16 by_q$16(
        .d(by_q$16$d),
        .q(by_q$16$q),
        .clock(by_q$16$clock)
    );
    top$lanes$1$ctl$by_q$17 by_q$17(
        .d(by_q$17$d),
        .q(by_q$17$q),
        .clock(by_q$17$clock)
    );
    top$lanes$1$ctl$by_q$18 by_q$18(
        .d(by_q$18$d),
        .q(by_q$18$q),
        .clock(by_q$18$clock)
    );
    top$lanes$1$ctl$by_q$19 by_q$19(
        .d(by_q$19$d),
        .q(by_q$19$q),
        .clock(by_q$19$clock)
    );
    top$lanes$1$ctl$by_q$20 by_q$20(
        .d(by_q$20$d),
        .q(by_q$20$q),
        .clock(by_q$20$clock)
    );
    top$lanes$1$ctl$face_q$0 face_q$0(
        .d(face_q$0$d),
        .q(face_q$0$q),
        .clock(face_q$0$clock)
    );
    top$lanes$1$ctl$face_q$1 face_q$1(
        .d(face_q$1$d),
        .q(face_q$1$q),
        .clock(face_q$1$clock)
    );
    top$lanes$1$ctl$face_q$2 face_q$2(
        .d(face_q$2$d),
        .q(face_q$2$q),
        .clock(face_q$2$clock)
    );
    top$lanes$1$ctl$face_q$3 face_q$3(
        .d(face_q$3$d),
        .q(face_q$3$q),
        .clock(face_q$3$clock)
    );
    top$lanes$1$ctl$face_q$4 face_q$4(
        .d(face_q$4$d),
        .q(face_q$4$q),
        .clock(face_q$4$clock)
    );
    top$lanes$1$ctl$face_q$5 face_q$5(
        .d(face_q$5$d),
        .q(face_q$5$q),
        .clock(face_q$5$clock)
    );
    top$lanes$1$ctl$face_q$6 face_q$6(
        .d(face_q$6$d),
        .q(face_q$6$q),
        .clock(face_q$6$clock)
    );
    top$lanes$1$ctl$face_q$7 face_q$7(
        .d(face_q$7$d),
        .q(face_q$7$q),
        .clock(face_q$7$clock)
    );
    top$lanes$1$ctl$face_q$8 face_q$8(
        .d(face_q$8$d),
        .q(face_q$8$q),
        .clock(face_q$8$clock)
    );
    top$lanes$1$ctl$face_q$9 face_q$9(
        .d(face_q$9$d),
        .q(face_q$9$q),
        .clock(face_q$9$clock)
    );
    top$lanes$1$ctl$face_q$10 face_q$10(
        .d(face_q$10$d),
        .q(face_q$10$q),
        .clock(face_q$10$clock)
    );
    top$lanes$1$ctl$face_q$11 face_q$11(
        .d(face_q$11$d),
        .q(face_q$11$q),
        .clock(face_q$11$clock)
    );
    top$lanes$1$ctl$face_q$12 face_q$12(
        .d(face_q$12$d),
        .q(face_q$12$q),
        .clock(face_q$12$clock)
    );
    top$lanes$1$ctl$face_q$13 face_q$13(
        .d(face_q$13$d),
        .q(face_q$13$q),
        .clock(face_q$13$clock)
    );
    top$lanes$1$ctl$face_q$14 face_q$14(
        .d(face_q$14$d),
        .q(face_q$14$q),
        .clock(face_q$14$clock)
    );
    top$lanes$1$ctl$face_q$15 face_q$15(
        .d(face_q$15$d),
        .q(face_q$15$q),
        .clock(face_q$15$clock)
    );
    top$lanes$1$ctl$face_q$16 face_q$16(
        .d(face_q$16$d),
        .q(face_q$16$q),
        .clock(face_q$16$clock)
    );
    top$lanes$1$ctl$face_q$17 face_q$17(
        .d(face_q$17$d),
        .q(face_q$17$q),
        .clock(face_q$17$clock)
    );
    top$lanes$1$ctl$face_q$18 face_q$18(
        .d(face_q$18$d),
        .q(face_q$18$q),
        .clock(face_q$18$clock)
    );
    top$lanes$1$ctl$face_q$19 face_q$19(
        .d(face_q$19$d),
        .q(face_q$19$q),
        .clock(face_q$19$clock)
    );
    top$lanes$1$ctl$face_q$20 face_q$20(
        .d(face_q$20$d),
        .q(face_q$20$q),
        .clock(face_q$20$clock)
    );
    
    // Update code
    always @(*) begin
        nx_last$clock = clock;
        ny_last$clock = clock;
        nx_last$d = nx_last$q;
        ny_last$d = ny_last$q;
        x_q$0$clock = clock;
        dxm_q$0$clock = clock;
        dym_q$0$clock = clock;
        x_q$1$clock = clock;
        dxm_q$1$clock = clock;
        dym_q$1$clock = clock;
        x_q$2$clock = clock;
        dxm_q$2$clock = clock;
        dym_q$2$clock = clock;
        x_q$3$clock = clock;
        dxm_q$3$clock = clock;
        dym_q$3$clock = clock;
        x_q$4$clock = clock;
        dxm_q$4$clock = clock;
        dym_q$4$clock = clock;
        x_q$5$clock = clock;
        dxm_q$5$clock = clock;
        dym_q$5$clock = clock;
        x_q$6$clock = clock;
        dxm_q$6$clock = clock;
        dym_q$6$clock = clock;
        x_q$7$clock = clock;
        dxm_q$7$clock = clock;
        dym_q$7$clock = clock;
        x_q$8$clock = clock;
        dxm_q$8$clock = clock;
        dym_q$8$clock = clock;
        x_q$9$clock = clock;
        dxm_q$9$clock = clock;
        dym_q$9$clock = clock;
        v_q$0$clock = clock;
        er_q$0$clock = clock;
        pad_q$0$clock = clock;
        bx_q$0$clock = clock;
        by_q$0$clock = clock;
        face_q$0$clock = clock;
        v_q$1$clock = clock;
        er_q$1$clock = clock;
        pad_q$1$clock = clock;
        bx_q$1$clock = clock;
        by_q$1$clock = clock;
        face_q$1$clock = clock;
        v_q$2$clock = clock;
        er_q$2$clock = clock;
        pad_q$2$clock = clock;
        bx_q$2$clock = clock;
        by_q$2$clock = clock;
        face_q$2$clock = clock;
        v_q$3$clock = clock;
        er_q$3$clock = clock;
        pad_q$3$clock = clock;
        bx_q$3$clock = clock;
        by_q$3$clock = clock;
        face_q$3$clock = clock;
        v_q$4$clock = clock;
        er_q$4$clock = clock;
        pad_q$4$clock = clock;
        bx_q$4$clock = clock;
        by_q$4$clock = clock;
        face_q$4$clock = clock;
        v_q$5$clock = clock;
        er_q$5$clock = clock;
        pad_q$5$clock = clock;
        bx_q$5$clock = clock;
        by_q$5$clock = clock;
        face_q$5$clock = clock;
        v_q$6$clock = clock;
        er_q$6$clock = clock;
        pad_q$6$clock = clock;
        bx_q$6$clock = clock;
        by_q$6$clock = clock;
        face_q$6$clock = clock;
        v_q$7$clock = clock;
        er_q$7$clock = clock;
        pad_q$7$clock = clock;
        bx_q$7$clock = clock;
        by_q$7$clock = clock;
        face_q$7$clock = clock;
        v_q$8$clock = clock;
        er_q$8$clock = clock;
        pad_q$8$clock = clock;
        bx_q$8$clock = clock;
        by_q$8$clock = clock;
        face_q$8$clock = clock;
        v_q$9$clock = clock;
        er_q$9$clock = clock;
        pad_q$9$clock = clock;
        bx_q$9$clock = clock;
        by_q$9$clock = clock;
        face_q$9$clock = clock;
        v_q$10$clock = clock;
        er_q$10$clock = clock;
        pad_q$10$clock = clock;
        bx_q$10$clock = clock;
        by_q$10$clock = clock;
        face_q$10$clock = clock;
        v_q$11$clock = clock;
        er_q$11$clock = clock;
        pad_q$11$clock = clock;
        bx_q$11$clock = clock;
        by_q$11$clock = clock;
        face_q$11$clock = clock;
        v_q$12$clock = clock;
        er_q$12$clock = clock;
        pad_q$12$clock = clock;
        bx_q$12$clock = clock;
        by_q$12$clock = clock;
        face_q$12$clock = clock;
        v_q$13$clock = clock;
        er_q$13$clock = clock;
        pad_q$13$clock = clock;
        bx_q$13$clock = clock;
        by_q$13$clock = clock;
        face_q$13$clock = clock;
        v_q$14$clock = clock;
        er_q$14$clock = clock;
        pad_q$14$clock = clock;
        bx_q$14$clock = clock;
        by_q$14$clock = clock;
        face_q$14$clock = clock;
        v_q$15$clock = clock;
        er_q$15$clock = clock;
        pad_q$15$clock = clock;
        bx_q$15$clock = clock;
        by_q$15$clock = clock;
        face_q$15$clock = clock;
        v_q$16$clock = clock;
        er_q$16$clock = clock;
        pad_q$16$clock = clock;
        bx_q$16$clock = clock;
        by_q$16$clock = clock;
        face_q$16$clock = clock;
        v_q$17$clock = clock;
        er_q$17$clock = clock;
        pad_q$17$clock = clock;
        bx_q$17$clock = clock;
        by_q$17$clock = clock;
        face_q$17$clock = clock;
        v_q$18$clock = clock;
        er_q$18$clock = clock;
        pad_q$18$clock = clock;
        bx_q$18$clock = clock;
        by_q$18$clock = clock;
        face_q$18$clock = clock;
        v_q$19$clock = clock;
        er_q$19$clock = clock;
        pad_q$19$clock = clock;
        bx_q$19$clock = clock;
        by_q$19$clock = clock;
        face_q$19$clock = clock;
        v_q$20$clock = clock;
        er_q$20$clock = clock;
        pad_q$20$clock = clock;
        bx_q$20$clock = clock;
        by_q$20$clock = clock;
        face_q$20$clock = clock;
        x_q$0$d = x & coord_mask;
        y_q$0$d = y & coord_mask;
        sr_q$0$d = sr;
        dxn_q$0$d = dx_neg;
        dxm_q$0$d = dx_mag;
        dyn_q$0$d = dy_neg;
        dym_q$0$d = dy_mag;
        x_q$1$d = x_q$0$q;
        dxm_q$1$d = dxm_q$0$q;
        dym_q$1$d = dym_q$0$q;
        x_q$2$d = x_q$1$q;
        dxm_q$2$d = dxm_q$1$q;
        dym_q$2$d = dym_q$1$q;
        x_q$3$d = x_q$2$q;
        dxm_q$3$d = dxm_q$2$q;
        dym_q$3$d = dym_q$2$q;
        x_q$4$d = x_q$3$q;
        dxm_q$4$d = dxm_q$3$q;
        dym_q$4$d = dym_q$3$q;
        x_q$5$d = x_q$4$q;
        dxm_q$5$d = dxm_q$4$q;
        dym_q$5$d = dym_q$4$q;
        x_q$6$d = x_q$5$q;
        dxm_q$6$d = dxm_q$5$q;
        dym_q$6$d = dym_q$5$q;
        x_q$7$d = x_q$6$q;
        dxm_q$7$d = dxm_q$6$q;
        dym_q$7$d = dym_q$6$q;
        x_q$8$d = x_q$7$q;
        dxm_q$8$d = dxm_q$7$q;
        dym_q$8$d = dym_q$7$q;
        x_q$9$d = x_q$8$q;
        dxm_q$9$d = dxm_q$8$q;
        dym_q$9$d = dym_q$8$q;
        y_q$0$clock = clock;
        sr_q$0$clock = clock;
        dxn_q$0$clock = clock;
        dyn_q$0$clock = clock;
        y_q$1$clock = clock;
        sr_q$1$clock = clock;
        dxn_q$1$clock = clock;
        dyn_q$1$clock = clock;
        y_q$2$clock = clock;
        sr_q$2$clock = clock;
        dxn_q$2$clock = clock;
        dyn_q$2$clock = clock;
        y_q$3$clock = clock;
        sr_q$3$clock = clock;
        dxn_q$3$clock = clock;
        dyn_q$3$clock = clock;
        y_q$4$clock = clock;
        sr_q$4$clock = clock;
        dxn_q$4$clock = clock;
        dyn_q$4$clock = clock;
        y_q$5$clock = clock;
        sr_q$5$clock = clock;
        dxn_q$5$clock = clock;
        dyn_q$5$clock = clock;
        y_q$6$clock = clock;
        sr_q$6$clock = clock;
        dxn_q$6$clock = clock;
        dyn_q$6$clock = clock;
        y_q$7$clock = clock;
        sr_q$7$clock = clock;
        dxn_q$7$clock = clock;
        dyn_q$7$clock = clock;
        y_q$8$clock = clock;
        sr_q$8$clock = clock;
        dxn_q$8$clock = clock;
        dyn_q$8$clock = clock;
        y_q$1$d = y_q$0$q;
        sr_q$1$d = sr_q$0$q;
        dxn_q$1$d = dxn_q$0$q;
        dyn_q$1$d = dyn_q$0$q;
        y_q$2$d = y_q$1$q;
        sr_q$2$d = sr_q$1$q;
        dxn_q$2$d = dxn_q$1$q;
        dyn_q$2$d = dyn_q$1$q;
        y_q$3$d = y_q$2$q;
        sr_q$3$d = sr_q$2$q;
        dxn_q$3$d = dxn_q$2$q;
        dyn_q$3$d = dyn_q$2$q;
        y_q$4$d = y_q$3$q;
        sr_q$4$d = sr_q$3$q;
        dxn_q$4$d = dxn_q$3$q;
        dyn_q$4$d = dyn_q$3$q;
        y_q$5$d = y_q$4$q;
        sr_q$5$d = sr_q$4$q;
        dxn_q$5$d = dxn_q$4$q;
        dyn_q$5$d = dyn_q$4$q;
        y_q$6$d = y_q$5$q;
        sr_q$6$d = sr_q$5$q;
        dxn_q$6$d = dxn_q$5$q;
        dyn_q$6$d = dyn_q$5$q;
        y_q$7$d = y_q$6$q;
        sr_q$7$d = sr_q$6$q;
        dxn_q$7$d = dxn_q$6$q;
        dyn_q$7$d = dyn_q$6$q;
        y_q$8$d = y_q$7$q;
        sr_q$8$d = sr_q$7$q;
        dxn_q$8$d = dxn_q$7$q;
        dyn_q$8$d = dyn_q$7$q;
        x_t = x_q$9$q;
        dx_mag_t = dxm_q$9$q;
        dy_mag_t = dym_q$9$q;
        nx_last$d = dims[('h0)+:(16)] - 'h1;
        ny_last$d = dims[('h10)+:(16)] - 'h1;
        x_out = 1'b0;
        if (dxm_q$8$q != 'h0) begin
            if (dxn_q$8$q) begin
                x_out = x_q$8$q == nx_last$q;
            end
            else begin
                x_out = x_q$8$q == 'h0;
            end
        end
        y_out = 1'b0;
        if (dym_q$8$q != 'h0) begin
            if (dyn_q$8$q) begin
                y_out = y_q$8$q == ny_last$q;
            end
            else begin
                y_out = y_q$8$q == 'h0;
            end
        end
        dx_nz = dxm_q$8$q != 'h0;
        dy_nz = dym_q$8$q != 'h0;
        sel = 7'(sr_q$8$q) | (7'(dxn_q$8$q) << 'h1) | (7'(dx_nz) << 'h2) | (7'(dyn_q$8$q) << 'h3) | (7'(dy_nz) << 'h4) | (7'(x_out) << 'h5) | (7'(y_out) << 'h6);
        sel_q$0$clock = clock;
        sel_q$0$d = sel;
        sel_t$0 = sel_q$0$q;
        sel_q$1$clock = clock;
        sel_q$1$d = sel;
        sel_t$1 = sel_q$1$q;
        sel_q$2$clock = clock;
        sel_q$2$d = sel;
        sel_t$2 = sel_q$2$q;
        sel_q$3$clock = clock;
        sel_q$3$d = sel;
        sel_t$3 = sel_q$3$q;
        v_q$0$d = valid;
        er_q$0$d = er;
        pad_q$0$d = pad;
        bx_q$0$d = base_x & coord_mask;
        by_q$0$d = base_y & coord_mask;
        face_q$0$d = face;
        v_q$1$d = v_q$0$q;
        er_q$1$d = er_q$0$q;
        pad_q$1$d = pad_q$0$q;
        bx_q$1$d = bx_q$0$q;
        by_q$1$d = by_q$0$q;
        face_q$1$d = face_q$0$q;
        v_q$2$d = v_q$1$q;
        er_q$2$d = er_q$1$q;
        pad_q$2$d = pad_q$1$q;
        bx_q$2$d = bx_q$1$q;
        by_q$2$d = by_q$1$q;
        face_q$2$d = face_q$1$q;
        v_q$3$d = v_q$2$q;
        er_q$3$d = er_q$2$q;
        pad_q$3$d = pad_q$2$q;
        bx_q$3$d = bx_q$2$q;
        by_q$3$d = by_q$2$q;
        face_q$3$d = face_q$2$q;
        v_q$4$d = v_q$3$q;
        er_q$4$d = er_q$3$q;
        pad_q$4$d = pad_q$3$q;
        bx_q$4$d = bx_q$3$q;
        by_q$4$d = by_q$3$q;
        face_q$4$d = face_q$3$q;
        v_q$5$d = v_q$4$q;
        er_q$5$d = er_q$4$q;
        pad_q$5$d = pad_q$4$q;
        bx_q$5$d = bx_q$4$q;
        by_q$5$d = by_q$4$q;
        face_q$5$d = face_q$4$q;
        v_q$6$d = v_q$5$q;
        er_q$6$d = er_q$5$q;
        pad_q$6$d = pad_q$5$q;
        bx_q$6$d = bx_q$5$q;
        by_q$6$d = by_q$5$q;
        face_q$6$d = face_q$5$q;
        v_q$7$d = v_q$6$q;
        er_q$7$d = er_q$6$q;
        pad_q$7$d = pad_q$6$q;
        bx_q$7$d = bx_q$6$q;
        by_q$7$d = by_q$6$q;
        face_q$7$d = face_q$6$q;
        v_q$8$d = v_q$7$q;
        er_q$8$d = er_q$7$q;
        pad_q$8$d = pad_q$7$q;
        bx_q$8$d = bx_q$7$q;
        by_q$8$d = by_q$7$q;
        face_q$8$d = face_q$7$q;
        v_q$9$d = v_q$8$q;
        er_q$9$d = er_q$8$q;
        pad_q$9$d = pad_q$8$q;
        bx_q$9$d = bx_q$8$q;
        by_q$9$d = by_q$8$q;
        face_q$9$d = face_q$8$q;
        v_q$10$d = v_q$9$q;
        er_q$10$d = er_q$9$q;
        pad_q$10$d = pad_q$9$q;
        bx_q$10$d = bx_q$9$q;
        by_q$10$d = by_q$9$q;
        face_q$10$d = face_q$9$q;
        v_q$11$d = v_q$10$q;
        er_q$11$d = er_q$10$q;
        pad_q$11$d = pad_q$10$q;
        bx_q$11$d = bx_q$10$q;
        by_q$11$d = by_q$10$q;
        face_q$11$d = face_q$10$q;
        v_q$12$d = v_q$11$q;
        er_q$12$d = er_q$11$q;
        pad_q$12$d = pad_q$11$q;
        bx_q$12$d = bx_q$11$q;
        by_q$12$d = by_q$11$q;
        face_q$12$d = face_q$11$q;
        v_q$13$d = v_q$12$q;
        er_q$13$d = er_q$12$q;
        pad_q$13$d = pad_q$12$q;
        bx_q$13$d = bx_q$12$q;
        by_q$13$d = by_q$12$q;
        face_q$13$d = face_q$12$q;
        v_q$14$d = v_q$13$q;
        er_q$14$d = er_q$13$q;
        pad_q$14$d = pad_q$13$q;
        bx_q$14$d = bx_q$13$q;
        by_q$14$d = by_q$13$q;
        face_q$14$d = face_q$13$q;
        v_q$15$d = v_q$14$q;
        er_q$15$d = er_q$14$q;
        pad_q$15$d = pad_q$14$q;
        bx_q$15$d = bx_q$14$q;
        by_q$15$d = by_q$14$q;
        face_q$15$d = face_q$14$q;
        v_q$16$d = v_q$15$q;
        er_q$16$d = er_q$15$q;
        pad_q$16$d = pad_q$15$q;
        bx_q$16$d = bx_q$15$q;
        by_q$16$d = by_q$15$q;
        face_q$16$d = face_q$15$q;
        v_q$17$d = v_q$16$q;
        er_q$17$d = er_q$16$q;
        pad_q$17$d = pad_q$16$q;
        bx_q$17$d = bx_q$16$q;
        by_q$17$d = by_q$16$q;
        face_q$17$d = face_q$16$q;
        v_q$18$d = v_q$17$q;
        er_q$18$d = er_q$17$q;
        pad_q$18$d = pad_q$17$q;
        bx_q$18$d = bx_q$17$q;
        by_q$18$d = by_q$17$q;
        face_q$18$d = face_q$17$q;
        v_q$19$d = v_q$18$q;
        er_q$19$d = er_q$18$q;
        pad_q$19$d = pad_q$18$q;
        bx_q$19$d = bx_q$18$q;
        by_q$19$d = by_q$18$q;
        face_q$19$d = face_q$18$q;
        v_q$20$d = v_q$19$q;
        er_q$20$d = er_q$19$q;
        pad_q$20$d = pad_q$19$q;
        bx_q$20$d = bx_q$19$q;
        by_q$20$d = by_q$19$q;
        face_q$20$d = face_q$19$q;
        res_beat = v_q$20$q;
        res_valid = v_q$20$q & ~pad_q$20$q;
        px_valid = v_q$20$q & er_q$20$q & ~pad_q$20$q;
        px_x = bx_q$20$q;
        px_y = by_q$20$q;
        px_face = face_q$20$q;
    end
    
endmodule // top$lanes$1$ctl
module top$lanes$1$ctl$bx_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$0
module top$lanes$1$ctl$bx_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$1
module top$lanes$1$ctl$bx_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$10
module top$lanes$1$ctl$bx_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$11
module top$lanes$1$ctl$bx_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$12
module top$lanes$1$ctl$bx_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$13
module top$lanes$1$ctl$bx_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$14
module top$lanes$1$ctl$bx_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$15
module top$lanes$1$ctl$bx_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$16
module top$lanes$1$ctl$bx_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$17
module top$lanes$1$ctl$bx_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$18
module top$lanes$1$ctl$bx_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$19
module top$lanes$1$ctl$bx_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$2
module top$lanes$1$ctl$bx_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$20
module top$lanes$1$ctl$bx_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$3
module top$lanes$1$ctl$bx_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$4
module top$lanes$1$ctl$bx_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$5
module top$lanes$1$ctl$bx_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$6
module top$lanes$1$ctl$bx_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$7
module top$lanes$1$ctl$bx_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$8
module top$lanes$1$ctl$bx_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$bx_q$9
module top$lanes$1$ctl$by_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$0
module top$lanes$1$ctl$by_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$1
module top$lanes$1$ctl$by_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$10
module top$lanes$1$ctl$by_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$11
module top$lanes$1$ctl$by_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$12
module top$lanes$1$ctl$by_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$13
module top$lanes$1$ctl$by_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$14
module top$lanes$1$ctl$by_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$15
module top$lanes$1$ctl$by_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$16
module top$lanes$1$ctl$by_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$17
module top$lanes$1$ctl$by_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$18
module top$lanes$1$ctl$by_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$19
module top$lanes$1$ctl$by_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$2
module top$lanes$1$ctl$by_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$20
module top$lanes$1$ctl$by_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$3
module top$lanes$1$ctl$by_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$4
module top$lanes$1$ctl$by_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$5
module top$lanes$1$ctl$by_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$6
module top$lanes$1$ctl$by_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$7
module top$lanes$1$ctl$by_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$8
module top$lanes$1$ctl$by_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$by_q$9
module top$lanes$1$ctl$dxm_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxm_q$0
module top$lanes$1$ctl$dxm_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxm_q$1
module top$lanes$1$ctl$dxm_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxm_q$2
module top$lanes$1$ctl$dxm_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxm_q$3
module top$lanes$1$ctl$dxm_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxm_q$4
module top$lanes$1$ctl$dxm_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxm_q$5
module top$lanes$1$ctl$dxm_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxm_q$6
module top$lanes$1$ctl$dxm_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxm_q$7
module top$lanes$1$ctl$dxm_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxm_q$8
module top$lanes$1$ctl$dxm_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxm_q$9
module top$lanes$1$ctl$dxn_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxn_q$0
module top$lanes$1$ctl$dxn_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxn_q$1
module top$lanes$1$ctl$dxn_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxn_q$2
module top$lanes$1$ctl$dxn_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxn_q$3
module top$lanes$1$ctl$dxn_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxn_q$4
module top$lanes$1$ctl$dxn_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxn_q$5
module top$lanes$1$ctl$dxn_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxn_q$6
module top$lanes$1$ctl$dxn_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxn_q$7
module top$lanes$1$ctl$dxn_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dxn_q$8
module top$lanes$1$ctl$dym_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dym_q$0
module top$lanes$1$ctl$dym_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dym_q$1
module top$lanes$1$ctl$dym_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dym_q$2
module top$lanes$1$ctl$dym_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dym_q$3
module top$lanes$1$ctl$dym_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dym_q$4
module top$lanes$1$ctl$dym_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dym_q$5
module top$lanes$1$ctl$dym_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dym_q$6
module top$lanes$1$ctl$dym_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dym_q$7
module top$lanes$1$ctl$dym_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dym_q$8
module top$lanes$1$ctl$dym_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dym_q$9
module top$lanes$1$ctl$dyn_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dyn_q$0
module top$lanes$1$ctl$dyn_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dyn_q$1
module top$lanes$1$ctl$dyn_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dyn_q$2
module top$lanes$1$ctl$dyn_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dyn_q$3
module top$lanes$1$ctl$dyn_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dyn_q$4
module top$lanes$1$ctl$dyn_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dyn_q$5
module top$lanes$1$ctl$dyn_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dyn_q$6
module top$lanes$1$ctl$dyn_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dyn_q$7
module top$lanes$1$ctl$dyn_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$dyn_q$8
module top$lanes$1$ctl$er_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$0
module top$lanes$1$ctl$er_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$1
module top$lanes$1$ctl$er_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$10
module top$lanes$1$ctl$er_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$11
module top$lanes$1$ctl$er_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$12
module top$lanes$1$ctl$er_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$13
module top$lanes$1$ctl$er_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$14
module top$lanes$1$ctl$er_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$15
module top$lanes$1$ctl$er_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$16
module top$lanes$1$ctl$er_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$17
module top$lanes$1$ctl$er_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$18
module top$lanes$1$ctl$er_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$19
module top$lanes$1$ctl$er_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$2
module top$lanes$1$ctl$er_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$20
module top$lanes$1$ctl$er_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$3
module top$lanes$1$ctl$er_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$4
module top$lanes$1$ctl$er_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$5
module top$lanes$1$ctl$er_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$6
module top$lanes$1$ctl$er_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$7
module top$lanes$1$ctl$er_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$8
module top$lanes$1$ctl$er_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$er_q$9
module top$lanes$1$ctl$face_q$0(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$0
module top$lanes$1$ctl$face_q$1(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$1
module top$lanes$1$ctl$face_q$10(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$10
module top$lanes$1$ctl$face_q$11(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$11
module top$lanes$1$ctl$face_q$12(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$12
module top$lanes$1$ctl$face_q$13(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$13
module top$lanes$1$ctl$face_q$14(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$14
module top$lanes$1$ctl$face_q$15(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$15
module top$lanes$1$ctl$face_q$16(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$16
module top$lanes$1$ctl$face_q$17(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$17
module top$lanes$1$ctl$face_q$18(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$18
module top$lanes$1$ctl$face_q$19(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$19
module top$lanes$1$ctl$face_q$2(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$2
module top$lanes$1$ctl$face_q$20(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$20
module top$lanes$1$ctl$face_q$3(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$3
module top$lanes$1$ctl$face_q$4(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$4
module top$lanes$1$ctl$face_q$5(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$5
module top$lanes$1$ctl$face_q$6(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$6
module top$lanes$1$ctl$face_q$7(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$7
module top$lanes$1$ctl$face_q$8(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$8
module top$lanes$1$ctl$face_q$9(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$ctl$face_q$9
module top$lanes$1$ctl$nx_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$ctl$nx_last
module top$lanes$1$ctl$ny_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$ctl$ny_last
module top$lanes$1$ctl$pad_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$0
module top$lanes$1$ctl$pad_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$1
module top$lanes$1$ctl$pad_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$10
module top$lanes$1$ctl$pad_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$11
module top$lanes$1$ctl$pad_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$12
module top$lanes$1$ctl$pad_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$13
module top$lanes$1$ctl$pad_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$14
module top$lanes$1$ctl$pad_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$15
module top$lanes$1$ctl$pad_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$16
module top$lanes$1$ctl$pad_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$17
module top$lanes$1$ctl$pad_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$18
module top$lanes$1$ctl$pad_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$19
module top$lanes$1$ctl$pad_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$2
module top$lanes$1$ctl$pad_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$20
module top$lanes$1$ctl$pad_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$3
module top$lanes$1$ctl$pad_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$4
module top$lanes$1$ctl$pad_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$5
module top$lanes$1$ctl$pad_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$6
module top$lanes$1$ctl$pad_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$7
module top$lanes$1$ctl$pad_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$8
module top$lanes$1$ctl$pad_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$pad_q$9
module top$lanes$1$ctl$sel_q$0(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$ctl$sel_q$0
module top$lanes$1$ctl$sel_q$1(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$ctl$sel_q$1
module top$lanes$1$ctl$sel_q$2(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$ctl$sel_q$2
module top$lanes$1$ctl$sel_q$3(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$ctl$sel_q$3
module top$lanes$1$ctl$sr_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$sr_q$0
module top$lanes$1$ctl$sr_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$sr_q$1
module top$lanes$1$ctl$sr_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$sr_q$2
module top$lanes$1$ctl$sr_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$sr_q$3
module top$lanes$1$ctl$sr_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$sr_q$4
module top$lanes$1$ctl$sr_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$sr_q$5
module top$lanes$1$ctl$sr_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$sr_q$6
module top$lanes$1$ctl$sr_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$sr_q$7
module top$lanes$1$ctl$sr_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$sr_q$8
module top$lanes$1$ctl$v_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$0
module top$lanes$1$ctl$v_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$1
module top$lanes$1$ctl$v_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$10
module top$lanes$1$ctl$v_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$11
module top$lanes$1$ctl$v_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$12
module top$lanes$1$ctl$v_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$13
module top$lanes$1$ctl$v_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$14
module top$lanes$1$ctl$v_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$15
module top$lanes$1$ctl$v_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$16
module top$lanes$1$ctl$v_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$17
module top$lanes$1$ctl$v_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$18
module top$lanes$1$ctl$v_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$19
module top$lanes$1$ctl$v_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$2
module top$lanes$1$ctl$v_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$20
module top$lanes$1$ctl$v_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$3
module top$lanes$1$ctl$v_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$4
module top$lanes$1$ctl$v_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$5
module top$lanes$1$ctl$v_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$6
module top$lanes$1$ctl$v_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$7
module top$lanes$1$ctl$v_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$8
module top$lanes$1$ctl$v_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$v_q$9
module top$lanes$1$ctl$x_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$x_q$0
module top$lanes$1$ctl$x_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$x_q$1
module top$lanes$1$ctl$x_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$x_q$2
module top$lanes$1$ctl$x_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$x_q$3
module top$lanes$1$ctl$x_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$x_q$4
module top$lanes$1$ctl$x_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$x_q$5
module top$lanes$1$ctl$x_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$x_q$6
module top$lanes$1$ctl$x_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$x_q$7
module top$lanes$1$ctl$x_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$x_q$8
module top$lanes$1$ctl$x_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$x_q$9
module top$lanes$1$ctl$y_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$y_q$0
module top$lanes$1$ctl$y_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$y_q$1
module top$lanes$1$ctl$y_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$y_q$2
module top$lanes$1$ctl$y_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$y_q$3
module top$lanes$1$ctl$y_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$y_q$4
module top$lanes$1$ctl$y_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$y_q$5
module top$lanes$1$ctl$y_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$y_q$6
module top$lanes$1$ctl$y_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$y_q$7
module top$lanes$1$ctl$y_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$ctl$y_q$8
module top$lanes$1$feed(clock,beats,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,o_valid,o_value,o_x,o_y,o_pad,o_invalid,o_sr,o_er,o_edge,o_face,o_base_x,o_base_y,o_dx_neg,o_dx_mag,o_dy_neg,o_dy_mag,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  o_valid;
    output reg  [15:0] o_value;
    output reg  [15:0] o_x;
    output reg  [15:0] o_y;
    output reg  o_pad;
    output reg  o_invalid;
    output reg  o_sr;
    output reg  o_er;
    output reg  o_edge;
    output reg  [2:0] o_face;
    output reg  [15:0] o_base_x;
    output reg  [15:0] o_base_y;
    output reg  o_dx_neg;
    output reg  [15:0] o_dx_mag;
    output reg  o_dy_neg;
    output reg  [15:0] o_dy_mag;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  use_gradient = 1'b0;
    
    // Stub signals
    reg  abc$clock;
    reg  [63:0] abc$beats;
    reg  [15:0] abc$value;
    reg  [15:0] abc$x;
    reg  [15:0] abc$from_left_xm;
    reg  [15:0] abc$from_left_ym;
    reg  [15:0] abc$from_left_zm;
    reg  [15:0] abc$from_right_xp;
    reg  [15:0] abc$from_right_yp;
    reg  [15:0] abc$from_right_zp;
    wire  [15:0] abc$to_right_xm = 'h0;
    wire  [15:0] abc$to_right_ym = 'h0;
    wire  [15:0] abc$to_right_zm = 'h0;
    wire  [15:0] abc$to_left_xp = 'h0;
    wire  [15:0] abc$to_left_yp = 'h0;
    wire  [15:0] abc$to_left_zp = 'h0;
    wire  [15:0] abc$o_value = 'h0;
    wire  abc$gx_neg = 'h0;
    wire  [15:0] abc$gx_mag = 'h0;
    wire  abc$gy_neg = 'h0;
    wire  [15:0] abc$gy_mag = 'h0;
    wire  abc$gz_neg = 'h0;
    wire  [15:0] abc$gz_mag = 'h0;
    
    // Sub module instances
    
    // Update code
    reg  [15:0] o_value_pass;
    always @(*) begin
        abc$clock = clock;
        abc$beats = beats;
        abc$value = value;
        abc$x = x;
        abc$from_left_xm = g_from_left_xm;
        abc$from_left_ym = g_from_left_ym;
        abc$from_left_zm = g_from_left_zm;
        abc$from_right_xp = g_from_right_xp;
        abc$from_right_yp = g_from_right_yp;
        abc$from_right_zp = g_from_right_zp;
        g_to_right_xm = abc$to_right_xm;
        g_to_right_ym = abc$to_right_ym;
        g_to_right_zm = abc$to_right_zm;
        g_to_left_xp = abc$to_left_xp;
        g_to_left_yp = abc$to_left_yp;
        g_to_left_zp = abc$to_left_zp;
        gx_neg = abc$gx_neg;
        gx_mag = abc$gx_mag;
        gy_neg = abc$gy_neg;
        gy_mag = abc$gy_mag;
        gz_neg = abc$gz_neg;
        gz_mag = abc$gz_mag;
        if (use_gradient) begin
            o_value_pass = abc$o_value;
        end
        else begin
            o_value_pass = value;
        end
        o_valid = beat_valid & ~halo;
        o_x = x;
        o_y = y;
        o_pad = pad;
        o_invalid = invalid;
        o_sr = sr;
        o_er = er;
        o_edge = at_edge;
        o_face = face;
        o_base_x = base_x;
        o_base_y = base_y;
        o_dx_neg = dx_neg;
        o_dx_mag = dx_mag;
        o_dy_neg = dy_neg;
        o_dy_mag = dy_mag;
        o_value = o_value_pass;
    end
    
endmodule // top$lanes$1$feed
module top$lanes$2(clock,host_write,host_address,host_data,dims,beats,order,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,res_beat,res_valid,res,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [63:0] dims;
    input wire  [63:0] beats;
    input wire  [63:0] order;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  res_beat;
    output reg  res_valid;
    output reg  [63:0] res;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Constant declarations
    localparam  coord_mask = 16'hff;
    
    // Stub signals
    reg  feed$clock;
    reg  [63:0] feed$beats;
    reg  feed$beat_valid;
    reg  [15:0] feed$value;
    reg  [15:0] feed$x;
    reg  [15:0] feed$y;
    reg  feed$pad;
    reg  feed$invalid;
    reg  feed$halo;
    reg  feed$sr;
    reg  feed$er;
    reg  [15:0] feed$base_x;
    reg  [15:0] feed$base_y;
    reg  [2:0] feed$face;
    reg  feed$at_edge;
    reg  feed$dx_neg;
    reg  [15:0] feed$dx_mag;
    reg  feed$dy_neg;
    reg  [15:0] feed$dy_mag;
    reg  [15:0] feed$g_from_left_xm;
    reg  [15:0] feed$g_from_left_ym;
    reg  [15:0] feed$g_from_left_zm;
    reg  [15:0] feed$g_from_right_xp;
    reg  [15:0] feed$g_from_right_yp;
    reg  [15:0] feed$g_from_right_zp;
    wire  [15:0] feed$g_to_right_xm;
    wire  [15:0] feed$g_to_right_ym;
    wire  [15:0] feed$g_to_right_zm;
    wire  [15:0] feed$g_to_left_xp;
    wire  [15:0] feed$g_to_left_yp;
    wire  [15:0] feed$g_to_left_zp;
    wire  feed$o_valid;
    wire  [15:0] feed$o_value;
    wire  [15:0] feed$o_x;
    wire  [15:0] feed$o_y;
    wire  feed$o_pad;
    wire  feed$o_invalid;
    wire  feed$o_sr;
    wire  feed$o_er;
    wire  feed$o_edge;
    wire  [2:0] feed$o_face;
    wire  [15:0] feed$o_base_x;
    wire  [15:0] feed$o_base_y;
    wire  feed$o_dx_neg;
    wire  [15:0] feed$o_dx_mag;
    wire  feed$o_dy_neg;
    wire  [15:0] feed$o_dy_mag;
    wire  feed$gx_neg;
    wire  [15:0] feed$gx_mag;
    wire  feed$gy_neg;
    wire  [15:0] feed$gy_mag;
    wire  feed$gz_neg;
    wire  [15:0] feed$gz_mag;
    reg  shader$clock;
    reg  shader$host_write;
    reg  [23:0] shader$host_address;
    reg  [63:0] shader$host_data;
    reg  [15:0] shader$value;
    reg  shader$invalid;
    reg  shader$at_edge;
    reg  shader$gx_neg;
    reg  [31:0] shader$gx_mag;
    reg  shader$gy_neg;
    reg  [31:0] shader$gy_mag;
    reg  shader$gz_neg;
    reg  [31:0] shader$gz_mag;
    wire  [31:0] shader$r;
    wire  [15:0] shader$g;
    wire  [15:0] shader$b;
    wire  [15:0] shader$a;
    wire  shader$valid;
    reg  ctl$clock;
    reg  ctl$valid;
    reg  ctl$er;
    reg  ctl$pad;
    reg  [15:0] ctl$base_x;
    reg  [15:0] ctl$base_y;
    reg  [2:0] ctl$face;
    reg  [15:0] ctl$x;
    reg  [15:0] ctl$y;
    reg  ctl$sr;
    reg  ctl$dx_neg;
    reg  [15:0] ctl$dx_mag;
    reg  ctl$dy_neg;
    reg  [15:0] ctl$dy_mag;
    reg  [63:0] ctl$dims;
    reg  [15:0] ctl$coord_mask;
    wire  [15:0] ctl$x_t;
    wire  [15:0] ctl$dx_mag_t;
    wire  [15:0] ctl$dy_mag_t;
    wire  [6:0] ctl$sel_t$0;
    wire  [6:0] ctl$sel_t$1;
    wire  [6:0] ctl$sel_t$2;
    wire  [6:0] ctl$sel_t$3;
    wire  ctl$res_beat;
    wire  ctl$res_valid;
    wire  ctl$px_valid;
    wire  [15:0] ctl$px_x;
    wire  [15:0] ctl$px_y;
    wire  [2:0] ctl$px_face;
    reg  taps$clock;
    reg  [63:0] taps$beats;
    reg  [15:0] taps$x;
    reg  [63:0] taps$res;
    reg  taps$res_beat;
    wire  [63:0] taps$t0s0;
    reg  [63:0] taps$t0i1;
    wire  [63:0] taps$t1s0;
    wire  [63:0] taps$t1s1;
    reg  [63:0] taps$t1i1;
    reg  [63:0] taps$t1i2;
    wire  [63:0] taps$t3s0;
    wire  [63:0] taps$t3s1;
    reg  [63:0] taps$t3i1;
    reg  [63:0] taps$t3i2;
    wire  [63:0] taps$t5s0;
    wire  [63:0] taps$t5s1;
    wire  [63:0] taps$t5s2;
    reg  [63:0] taps$t5i1;
    reg  [63:0] taps$t5i2;
    reg  [63:0] taps$t5i3;
    wire  [63:0] taps$t6s0;
    reg  [63:0] taps$t6i1;
    wire  [63:0] taps$t7s0;
    reg  [63:0] taps$t7i1;
    wire  [63:0] taps$t8s0;
    reg  [63:0] taps$t8i1;
    reg  [63:0] taps$t8il;
    wire  [63:0] taps$a$0;
    wire  [63:0] taps$a$1;
    wire  [63:0] taps$a$2;
    wire  [63:0] taps$a$3;
    wire  [63:0] taps$a$4;
    wire  [63:0] taps$a$5;
    wire  [63:0] taps$a$6;
    wire  [63:0] taps$a$7;
    wire  [63:0] taps$a$8;
    reg  [63:0] cells$a$0;
    reg  [63:0] cells$a$1;
    reg  [63:0] cells$a$2;
    reg  [63:0] cells$a$3;
    reg  [63:0] cells$a$4;
    reg  [63:0] cells$a$5;
    reg  [63:0] cells$a$6;
    reg  [63:0] cells$a$7;
    reg  [63:0] cells$a$8;
    reg  [6:0] cells$sel$0;
    reg  [6:0] cells$sel$1;
    reg  [6:0] cells$sel$2;
    reg  [6:0] cells$sel$3;
    wire  [31:0] cells$c00$0;
    wire  [31:0] cells$c00$1;
    wire  [31:0] cells$c00$2;
    wire  [31:0] cells$c00$3;
    wire  [31:0] cells$c10$0;
    wire  [31:0] cells$c10$1;
    wire  [31:0] cells$c10$2;
    wire  [31:0] cells$c10$3;
    wire  [31:0] cells$c01$0;
    wire  [31:0] cells$c01$1;
    wire  [31:0] cells$c01$2;
    wire  [31:0] cells$c01$3;
    wire  [31:0] cells$c11$0;
    wire  [31:0] cells$c11$1;
    wire  [31:0] cells$c11$2;
    wire  [31:0] cells$c11$3;
    reg  [63:0] cells$order;
    reg  bilinear$clock;
    reg  [31:0] bilinear$c00$0;
    reg  [31:0] bilinear$c00$1;
    reg  [31:0] bilinear$c00$2;
    reg  [31:0] bilinear$c00$3;
    reg  [31:0] bilinear$c10$0;
    reg  [31:0] bilinear$c10$1;
    reg  [31:0] bilinear$c10$2;
    reg  [31:0] bilinear$c10$3;
    reg  [31:0] bilinear$c01$0;
    reg  [31:0] bilinear$c01$1;
    reg  [31:0] bilinear$c01$2;
    reg  [31:0] bilinear$c01$3;
    reg  [31:0] bilinear$c11$0;
    reg  [31:0] bilinear$c11$1;
    reg  [31:0] bilinear$c11$2;
    reg  [31:0] bilinear$c11$3;
    reg  [15:0] bilinear$wx;
    reg  [15:0] bilinear$wy;
    wire  [31:0] bilinear$out$0;
    wire  [31:0] bilinear$out$1;
    wire  [31:0] bilinear$out$2;
    wire  [31:0] bilinear$out$3;
    reg  compositor$clock;
    reg  [31:0] compositor$acc_r;
    reg  [15:0] compositor$acc_g;
    reg  [15:0] compositor$acc_b;
    reg  [15:0] compositor$acc_a;
    reg  [31:0] compositor$new_r;
    reg  [15:0] compositor$new_g;
    reg  [15:0] compositor$new_b;
    reg  [15:0] compositor$new_a;
    reg  compositor$new_valid;
    wire  [31:0] compositor$out_r;
    wire  [15:0] compositor$out_g;
    wire  [15:0] compositor$out_b;
    wire  [15:0] compositor$out_a;
    reg  [63:0] compositor$order;
    
    // Sub module instances
    top$lanes$2$feed feed(
        .clock(feed$clock),
        .beats(feed$beats),
        .beat_valid(feed$beat_valid),
        .value(feed$value),
        .x(feed$x),
        .y(feed$y),
        .pad(feed$pad),
        .invalid(feed$invalid),
        .halo(feed$halo),
        .sr(feed$sr),
        .er(feed$er),
        .base_x(feed$base_x),
        .base_y(feed$base_y),
        .face(feed$face),
        .at_edge(feed$at_edge),
        .dx_neg(feed$dx_neg),
        .dx_mag(feed$dx_mag),
        .dy_neg(feed$dy_neg),
        .dy_mag(feed$dy_mag),
        .g_from_left_xm(feed$g_from_left_xm),
        .g_from_left_ym(feed$g_from_left_ym),
        .g_from_left_zm(feed$g_from_left_zm),
        .g_from_right_xp(feed$g_from_right_xp),
        .g_from_right_yp(feed$g_from_right_yp),
        .g_from_right_zp(feed$g_from_right_zp),
        .g_to_right_xm(feed$g_to_right_xm),
        .g_to_right_ym(feed$g_to_right_ym),
        .g_to_right_zm(feed$g_to_right_zm),
        .g_to_left_xp(feed$g_to_left_xp),
        .g_to_left_yp(feed$g_to_left_yp),
        .g_to_left_zp(feed$g_to_left_zp),
        .o_valid(feed$o_valid),
        .o_value(feed$o_value),
        .o_x(feed$o_x),
        .o_y(feed$o_y),
        .o_pad(feed$o_pad),
        .o_invalid(feed$o_invalid),
        .o_sr(feed$o_sr),
        .o_er(feed$o_er),
        .o_edge(feed$o_edge),
        .o_face(feed$o_face),
        .o_base_x(feed$o_base_x),
        .o_base_y(feed$o_base_y),
        .o_dx_neg(feed$o_dx_neg),
        .o_dx_mag(feed$o_dx_mag),
        .o_dy_neg(feed$o_dy_neg),
        .o_dy_mag(feed$o_dy_mag),
        .gx_neg(feed$gx_neg),
        .gx_mag(feed$gx_mag),
        .gy_neg(feed$gy_neg),
        .gy_mag(feed$gy_mag),
        .gz_neg(feed$gz_neg),
        .gz_mag(feed$gz_mag)
    );
    top$lanes$2$shader shader(
        .clock(shader$clock),
        .host_write(shader$host_write),
        .host_address(shader$host_address),
        .host_data(shader$host_data),
        .value(shader$value),
        .invalid(shader$invalid),
        .at_edge(shader$at_edge),
        .gx_neg(shader$gx_neg),
        .gx_mag(shader$gx_mag),
        .gy_neg(shader$gy_neg),
        .gy_mag(shader$gy_mag),
        .gz_neg(shader$gz_neg),
        .gz_mag(shader$gz_mag),
        .r(shader$r),
        .g(shader$g),
        .b(shader$b),
        .a(shader$a),
        .valid(shader$valid)
    );
    top$lanes$2$ctl ctl(
        .clock(ctl$clock),
        .valid(ctl$valid),
        .er(ctl$er),
        .pad(ctl$pad),
        .base_x(ctl$base_x),
        .base_y(ctl$base_y),
        .face(ctl$face),
        .x(ctl$x),
        .y(ctl$y),
        .sr(ctl$sr),
        .dx_neg(ctl$dx_neg),
        .dx_mag(ctl$dx_mag),
        .dy_neg(ctl$dy_neg),
        .dy_mag(ctl$dy_mag),
        .dims(ctl$dims),
        .coord_mask(ctl$coord_mask),
        .x_t(ctl$x_t),
        .dx_mag_t(ctl$dx_mag_t),
        .dy_mag_t(ctl$dy_mag_t),
        .sel_t$0(ctl$sel_t$0),
        .sel_t$1(ctl$sel_t$1),
        .sel_t$2(ctl$sel_t$2),
        .sel_t$3(ctl$sel_t$3),
        .res_beat(ctl$res_beat),
        .res_valid(ctl$res_valid),
        .px_valid(ctl$px_valid),
        .px_x(ctl$px_x),
        .px_y(ctl$px_y),
        .px_face(ctl$px_face)
    );
    top$lanes$2$taps taps(
        .clock(taps$clock),
        .beats(taps$beats),
        .x(taps$x),
        .res(taps$res),
        .res_beat(taps$res_beat),
        .t0s0(taps$t0s0),
        .t0i1(taps$t0i1),
        .t1s0(taps$t1s0),
        .t1s1(taps$t1s1),
        .t1i1(taps$t1i1),
        .t1i2(taps$t1i2),
        .t3s0(taps$t3s0),
        .t3s1(taps$t3s1),
        .t3i1(taps$t3i1),
        .t3i2(taps$t3i2),
        .t5s0(taps$t5s0),
        .t5s1(taps$t5s1),
        .t5s2(taps$t5s2),
        .t5i1(taps$t5i1),
        .t5i2(taps$t5i2),
        .t5i3(taps$t5i3),
        .t6s0(taps$t6s0),
        .t6i1(taps$t6i1),
        .t7s0(taps$t7s0),
        .t7i1(taps$t7i1),
        .t8s0(taps$t8s0),
        .t8i1(taps$t8i1),
        .t8il(taps$t8il),
        .a$0(taps$a$0),
        .a$1(taps$a$1),
        .a$2(taps$a$2),
        .a$3(taps$a$3),
        .a$4(taps$a$4),
        .a$5(taps$a$5),
        .a$6(taps$a$6),
        .a$7(taps$a$7),
        .a$8(taps$a$8)
    );
    top$lanes$2$cells cells(
        .a$0(cells$a$0),
        .a$1(cells$a$1),
        .a$2(cells$a$2),
        .a$3(cells$a$3),
        .a$4(cells$a$4),
        .a$5(cells$a$5),
        .a$6(cells$a$6),
        .a$7(cells$a$7),
        .a$8(cells$a$8),
        .sel$0(cells$sel$0),
        .sel$1(cells$sel$1),
        .sel$2(cells$sel$2),
        .sel$3(cells$sel$3),
        .c00$0(cells$c00$0),
        .c00$1(cells$c00$1),
        .c00$2(cells$c00$2),
        .c00$3(cells$c00$3),
        .c10$0(cells$c10$0),
        .c10$1(cells$c10$1),
        .c10$2(cells$c10$2),
        .c10$3(cells$c10$3),
        .c01$0(cells$c01$0),
        .c01$1(cells$c01$1),
        .c01$2(cells$c01$2),
        .c01$3(cells$c01$3),
        .c11$0(cells$c11$0),
        .c11$1(cells$c11$1),
        .c11$2(cells$c11$2),
        .c11$3(cells$c11$3),
        .order(cells$order)
    );
    top$lanes$2$bilinear bilinear(
        .clock(bilinear$clock),
        .c00$0(bilinear$c00$0),
        .c00$1(bilinear$c00$1),
        .c00$2(bilinear$c00$2),
        .c00$3(bilinear$c00$3),
        .c10$0(bilinear$c10$0),
        .c10$1(bilinear$c10$1),
        .c10$2(bilinear$c10$2),
        .c10$3(bilinear$c10$3),
        .c01$0(bilinear$c01$0),
        .c01$1(bilinear$c01$1),
        .c01$2(bilinear$c01$2),
        .c01$3(bilinear$c01$3),
        .c11$0(bilinear$c11$0),
        .c11$1(bilinear$c11$1),
        .c11$2(bilinear$c11$2),
        .c11$3(bilinear$c11$3),
        .wx(bilinear$wx),
        .wy(bilinear$wy),
        .out$0(bilinear$out$0),
        .out$1(bilinear$out$1),
        .out$2(bilinear$out$2),
        .out$3(bilinear$out$3)
    );
    top$lanes$2$compositor compositor(
        .clock(compositor$clock),
        .acc_r(compositor$acc_r),
        .acc_g(compositor$acc_g),
        .acc_b(compositor$acc_b),
        .acc_a(compositor$acc_a),
        .new_r(compositor$new_r),
        .new_g(compositor$new_g),
        .new_b(compositor$new_b),
        .new_a(compositor$new_a),
        .new_valid(compositor$new_valid),
        .out_r(compositor$out_r),
        .out_g(compositor$out_g),
        .out_b(compositor$out_b),
        .out_a(compositor$out_a),
        .order(compositor$order)
    );
    
    // Update code
    always @(*) begin
        feed$clock = clock;
        feed$beats = beats;
        feed$beat_valid = beat_valid;
        feed$value = value;
        feed$x = x;
        feed$y = y;
        feed$pad = pad;
        feed$invalid = invalid;
        feed$halo = halo;
        feed$sr = sr;
        feed$er = er;
        feed$base_x = base_x;
        feed$base_y = base_y;
        feed$face = face;
        feed$at_edge = at_edge;
        feed$dx_neg = dx_neg;
        feed$dx_mag = dx_mag;
        feed$dy_neg = dy_neg;
        feed$dy_mag = dy_mag;
        feed$g_from_left_xm = g_from_left_xm;
        feed$g_from_left_ym = g_from_left_ym;
        feed$g_from_left_zm = g_from_left_zm;
        feed$g_from_right_xp = g_from_right_xp;
        feed$g_from_right_yp = g_from_right_yp;
        feed$g_from_right_zp = g_from_right_zp;
        g_to_right_xm = feed$g_to_right_xm;
        g_to_right_ym = feed$g_to_right_ym;
        g_to_right_zm = feed$g_to_right_zm;
        g_to_left_xp = feed$g_to_left_xp;
        g_to_left_yp = feed$g_to_left_yp;
        g_to_left_zp = feed$g_to_left_zp;
        shader$clock = clock;
        shader$host_write = host_write;
        shader$host_address = host_address;
        shader$host_data = host_data;
        shader$value = feed$o_value;
        shader$invalid = feed$o_invalid;
        shader$at_edge = feed$o_edge;
        shader$gx_neg = feed$gx_neg;
        shader$gx_mag = 32'(feed$gx_mag);
        shader$gy_neg = feed$gy_neg;
        shader$gy_mag = 32'(feed$gy_mag);
        shader$gz_neg = feed$gz_neg;
        shader$gz_mag = 32'(feed$gz_mag);
        ctl$clock = clock;
        ctl$valid = feed$o_valid;
        ctl$er = feed$o_er;
        ctl$pad = feed$o_pad;
        ctl$coord_mask = coord_mask;
        ctl$base_x = feed$o_base_x;
        ctl$base_y = feed$o_base_y;
        ctl$face = feed$o_face;
        ctl$x = feed$o_x;
        ctl$y = feed$o_y;
        ctl$sr = feed$o_sr;
        ctl$dx_neg = feed$o_dx_neg;
        ctl$dx_mag = feed$o_dx_mag;
        ctl$dy_neg = feed$o_dy_neg;
        ctl$dy_mag = feed$o_dy_mag;
        ctl$dims = dims;
        taps$clock = clock;
        taps$beats = beats;
        taps$x = ctl$x_t;
        t0s0 = taps$t0s0;
        taps$t0i1 = t0i1;
        t1s0 = taps$t1s0;
        t1s1 = taps$t1s1;
        taps$t1i1 = t1i1;
        taps$t1i2 = t1i2;
        t3s0 = taps$t3s0;
        t3s1 = taps$t3s1;
        taps$t3i1 = t3i1;
        taps$t3i2 = t3i2;
        t5s0 = taps$t5s0;
        t5s1 = taps$t5s1;
        t5s2 = taps$t5s2;
        taps$t5i1 = t5i1;
        taps$t5i2 = t5i2;
        taps$t5i3 = t5i3;
        t6s0 = taps$t6s0;
        taps$t6i1 = t6i1;
        t7s0 = taps$t7s0;
        taps$t7i1 = t7i1;
        t8s0 = taps$t8s0;
        taps$t8i1 = t8i1;
        taps$t8il = t8il;
        cells$a$0 = taps$a$0;
        cells$a$1 = taps$a$1;
        cells$a$2 = taps$a$2;
        cells$a$3 = taps$a$3;
        cells$a$4 = taps$a$4;
        cells$a$5 = taps$a$5;
        cells$a$6 = taps$a$6;
        cells$a$7 = taps$a$7;
        cells$a$8 = taps$a$8;
        cells$order = order;
        cells$sel$0 = ctl$sel_t$0;
        cells$sel$1 = ctl$sel_t$1;
        cells$sel$2 = ctl$sel_t$2;
        cells$sel$3 = ctl$sel_t$3;
        bilinear$clock = clock;
        bilinear$c00$0 = cells$c00$0;
        bilinear$c10$0 = cells$c10$0;
        bilinear$c01$0 = cells$c01$0;
        bilinear$c11$0 = cells$c11$0;
        bilinear$c00$1 = cells$c00$1;
        bilinear$c10$1 = cells$c10$1;
        bilinear$c01$1 = cells$c01$1;
        bilinear$c11$1 = cells$c11$1;
        bilinear$c00$2 = cells$c00$2;
        bilinear$c10$2 = cells$c10$2;
        bilinear$c01$2 = cells$c01$2;
        bilinear$c11$2 = cells$c11$2;
        bilinear$c00$3 = cells$c00$3;
        bilinear$c10$3 = cells$c10$3;
        bilinear$c01$3 = cells$c01$3;
        bilinear$c11$3 = cells$c11$3;
        bilinear$wx = ctl$dx_mag_t;
        bilinear$wy = ctl$dy_mag_t;
        compositor$clock = clock;
        compositor$order = order;
        compositor$acc_r = bilinear$out$0;
        compositor$acc_g = 16'(bilinear$out$1);
        compositor$acc_b = 16'(bilinear$out$2);
        compositor$acc_a = 16'(bilinear$out$3);
        compositor$new_r = shader$r;
        compositor$new_g = shader$g;
        compositor$new_b = shader$b;
        compositor$new_a = shader$a;
        compositor$new_valid = shader$valid;
        res = 64'(compositor$out_r) | (64'(compositor$out_g) << 'h10) | (64'(compositor$out_b) << 'h20) | (64'(compositor$out_a) << 'h30);
        taps$res = res;
        taps$res_beat = ctl$res_beat;
        res_beat = ctl$res_beat;
        res_valid = ctl$res_valid;
        px_valid = ctl$px_valid;
        px_x = ctl$px_x;
        px_y = ctl$px_y;
        px_face = ctl$px_face;
    end
    
endmodule // top$lanes$2
module top$lanes$2$cells(a$0,a$1,a$2,a$3,a$4,a$5,a$6,a$7,a$8,sel$0,sel$1,sel$2,sel$3,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,order);
    
    // Module arguments
    input wire  [63:0] a$0;
    input wire  [63:0] a$1;
    input wire  [63:0] a$2;
    input wire  [63:0] a$3;
    input wire  [63:0] a$4;
    input wire  [63:0] a$5;
    input wire  [63:0] a$6;
    input wire  [63:0] a$7;
    input wire  [63:0] a$8;
    input wire  [6:0] sel$0;
    input wire  [6:0] sel$1;
    input wire  [6:0] sel$2;
    input wire  [6:0] sel$3;
    output reg  [31:0] c00$0;
    output reg  [31:0] c00$1;
    output reg  [31:0] c00$2;
    output reg  [31:0] c00$3;
    output reg  [31:0] c10$0;
    output reg  [31:0] c10$1;
    output reg  [31:0] c10$2;
    output reg  [31:0] c10$3;
    output reg  [31:0] c01$0;
    output reg  [31:0] c01$1;
    output reg  [31:0] c01$2;
    output reg  [31:0] c01$3;
    output reg  [31:0] c11$0;
    output reg  [31:0] c11$1;
    output reg  [31:0] c11$2;
    output reg  [31:0] c11$3;
    input wire  [63:0] order;
    
    // Constant declarations
    localparam  vmax = 64'hff;
    localparam  r_mask = 64'hffff;
    localparam  gba_mask = 64'hffff;
    
    // Local signals
    reg  [63:0] reset;
    reg  [63:0] w00$0;
    reg  [63:0] w00$1;
    reg  [63:0] w00$2;
    reg  [63:0] w00$3;
    reg  [63:0] w10$0;
    reg  [63:0] w10$1;
    reg  [63:0] w10$2;
    reg  [63:0] w10$3;
    reg  [63:0] w01$0;
    reg  [63:0] w01$1;
    reg  [63:0] w01$2;
    reg  [63:0] w01$3;
    reg  [63:0] w11$0;
    reg  [63:0] w11$1;
    reg  [63:0] w11$2;
    reg  [63:0] w11$3;
    
    // Update code
    always @(*) begin
        reset = 'h0;
        if (order['h1]) begin
            reset = vmax;
        end
        w00$0 = a$0;
        w10$0 = a$0;
        w01$0 = a$0;
        if (sel$0['h2]) begin
            if (sel$0['h1]) begin
                w10$0 = a$2;
            end
            else begin
                w10$0 = a$1;
            end
        end
        if (sel$0['h4]) begin
            if (sel$0['h3]) begin
                w01$0 = a$4;
            end
            else begin
                w01$0 = a$3;
            end
        end
        w11$0 = w01$0;
        if (sel$0['h2]) begin
            w11$0 = w10$0;
            if (sel$0['h4]) begin
                if (sel$0['h1]) begin
                    if (sel$0['h3]) begin
                        w11$0 = a$8;
                    end
                    else begin
                        w11$0 = a$6;
                    end
                end
                else if (sel$0['h3]) begin
                    w11$0 = a$7;
                end
                else begin
                    w11$0 = a$5;
                end
            end
        end
        if (sel$0['h5]) begin
            w10$0 = reset;
            w11$0 = reset;
        end
        if (sel$0['h6]) begin
            w01$0 = reset;
            w11$0 = reset;
        end
        if (sel$0['h0]) begin
            w00$0 = reset;
            w10$0 = reset;
            w01$0 = reset;
            w11$0 = reset;
        end
        w00$1 = a$0;
        w10$1 = a$0;
        w01$1 = a$0;
        if (sel$1['h2]) begin
            if (sel$1['h1]) begin
                w10$1 = a$2;
            end
            else begin
                w10$1 = a$1;
            end
        end
        if (sel$1['h4]) begin
            if (sel$1['h3]) begin
                w01$1 = a$4;
            end
            else begin
                w01$1 = a$3;
            end
        end
        w11$1 = w01$1;
        if (sel$1['h2]) begin
            w11$1 = w10$1;
            if (sel$1['h4]) begin
                if (sel$1['h1]) begin
                    if (sel$1['h3]) begin
                        w11$1 = a$8;
                    end
                    else begin
                        w11$1 = a$6;
                    end
                end
                else if (sel$1['h3]) begin
                    w11$1 = a$7;
                end
                else begin
                    w11$1 = a$5;
                end
            end
        end
        if (sel$1['h5]) begin
            w10$1 = reset;
            w11$1 = reset;
        end
        if (sel$1['h6]) begin
            w01$1 = reset;
            w11$1 = reset;
        end
        if (sel$1['h0]) begin
            w00$1 = reset;
            w10$1 = reset;
            w01$1 = reset;
            w11$1 = reset;
        end
        w00$2 = a$0;
        w10$2 = a$0;
        w01$2 = a$0;
        if (sel$2['h2]) begin
            if (sel$2['h1]) begin
                w10$2 = a$2;
            end
            else begin
                w10$2 = a$1;
            end
        end
        if (sel$2['h4]) begin
            if (sel$2['h3]) begin
                w01$2 = a$4;
            end
            else begin
                w01$2 = a$3;
            end
        end
        w11$2 = w01$2;
        if (sel$2['h2]) begin
            w11$2 = w10$2;
            if (sel$2['h4]) begin
                if (sel$2['h1]) begin
                    if (sel$2['h3]) begin
                        w11$2 = a$8;
                    end
                    else begin
                        w11$2 = a$6;
                    end
                end
                else if (sel$2['h3]) begin
                    w11$2 = a$7;
                end
                else begin
                    w11$2 = a$5;
                end
            end
        end
        if (sel$2['h5]) begin
            w10$2 = reset;
            w11$2 = reset;
        end
        if (sel$2['h6]) begin
            w01$2 = reset;
            w11$2 = reset;
        end
        if (sel$2['h0]) begin
            w00$2 = reset;
            w10$2 = reset;
            w01$2 = reset;
            w11$2 = reset;
        end
        w00$3 = a$0;
        w10$3 = a$0;
        w01$3 = a$0;
        if (sel$3['h2]) begin
            if (sel$3['h1]) begin
                w10$3 = a$2;
            end
            else begin
                w10$3 = a$1;
            end
        end
        if (sel$3['h4]) begin
            if (sel$3['h3]) begin
                w01$3 = a$4;
            end
            else begin
                w01$3 = a$3;
            end
        end
        w11$3 = w01$3;
        if (sel$3['h2]) begin
            w11$3 = w10$3;
            if (sel$3['h4]) begin
                if (sel$3['h1]) begin
                    if (sel$3['h3]) begin
                        w11$3 = a$8;
                    end
                    else begin
                        w11$3 = a$6;
                    end
                end
                else if (sel$3['h3]) begin
                    w11$3 = a$7;
                end
                else begin
                    w11$3 = a$5;
                end
            end
        end
        if (sel$3['h5]) begin
            w10$3 = reset;
            w11$3 = reset;
        end
        if (sel$3['h6]) begin
            w01$3 = reset;
            w11$3 = reset;
        end
        if (sel$3['h0]) begin
            w00$3 = reset;
            w10$3 = reset;
            w01$3 = reset;
            w11$3 = reset;
        end
        c00$0 = 32'(w00$0 & r_mask);
        c00$1 = 32'((w00$1 >> 'h10) & gba_mask);
        c00$2 = 32'((w00$2 >> 'h20) & gba_mask);
        c00$3 = 32'((w00$3 >> 'h30) & gba_mask);
        c10$0 = 32'(w10$0 & r_mask);
        c10$1 = 32'((w10$1 >> 'h10) & gba_mask);
        c10$2 = 32'((w10$2 >> 'h20) & gba_mask);
        c10$3 = 32'((w10$3 >> 'h30) & gba_mask);
        c01$0 = 32'(w01$0 & r_mask);
        c01$1 = 32'((w01$1 >> 'h10) & gba_mask);
        c01$2 = 32'((w01$2 >> 'h20) & gba_mask);
        c01$3 = 32'((w01$3 >> 'h30) & gba_mask);
        c11$0 = 32'(w11$0 & r_mask);
        c11$1 = 32'((w11$1 >> 'h10) & gba_mask);
        c11$2 = 32'((w11$2 >> 'h20) & gba_mask);
        c11$3 = 32'((w11$3 >> 'h30) & gba_mask);
    end
    
endmodule // top$lanes$2$cells
module top$lanes$2$ctl(clock,valid,er,pad,base_x,base_y,face,x,y,sr,dx_neg,dx_mag,dy_neg,dy_mag,dims,coord_mask,x_t,dx_mag_t,dy_mag_t,sel_t$0,sel_t$1,sel_t$2,sel_t$3,res_beat,res_valid,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  valid;
    input wire  er;
    input wire  pad;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  sr;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [63:0] dims;
    input wire  [15:0] coord_mask;
    output reg  [15:0] x_t;
    output reg  [15:0] dx_mag_t;
    output reg  [15:0] dy_mag_t;
    output reg  [6:0] sel_t$0;
    output reg  [6:0] sel_t$1;
    output reg  [6:0] sel_t$2;
    output reg  [6:0] sel_t$3;
    output reg  res_beat;
    output reg  res_valid;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Stub signals
    reg  [15:0] nx_last$d;
    wire  [15:0] nx_last$q;
    reg  nx_last$clock;
    reg  [15:0] ny_last$d;
    wire  [15:0] ny_last$q;
    reg  ny_last$clock;
    reg  [6:0] sel_q$0$d;
    wire  [6:0] sel_q$0$q;
    reg  sel_q$0$clock;
    reg  [6:0] sel_q$1$d;
    wire  [6:0] sel_q$1$q;
    reg  sel_q$1$clock;
    reg  [6:0] sel_q$2$d;
    wire  [6:0] sel_q$2$q;
    reg  sel_q$2$clock;
    reg  [6:0] sel_q$3$d;
    wire  [6:0] sel_q$3$q;
    reg  sel_q$3$clock;
    reg  [15:0] x_q$0$d;
    wire  [15:0] x_q$0$q;
    reg  x_q$0$clock;
    reg  [15:0] x_q$1$d;
    wire  [15:0] x_q$1$q;
    reg  x_q$1$clock;
    reg  [15:0] x_q$2$d;
    wire  [15:0] x_q$2$q;
    reg  x_q$2$clock;
    reg  [15:0] x_q$3$d;
    wire  [15:0] x_q$3$q;
    reg  x_q$3$clock;
    reg  [15:0] x_q$4$d;
    wire  [15:0] x_q$4$q;
    reg  x_q$4$clock;
    reg  [15:0] x_q$5$d;
    wire  [15:0] x_q$5$q;
    reg  x_q$5$clock;
    reg  [15:0] x_q$6$d;
    wire  [15:0] x_q$6$q;
    reg  x_q$6$clock;
    reg  [15:0] x_q$7$d;
    wire  [15:0] x_q$7$q;
    reg  x_q$7$clock;
    reg  [15:0] x_q$8$d;
    wire  [15:0] x_q$8$q;
    reg  x_q$8$clock;
    reg  [15:0] x_q$9$d;
    wire  [15:0] x_q$9$q;
    reg  x_q$9$clock;
    reg  [15:0] y_q$0$d;
    wire  [15:0] y_q$0$q;
    reg  y_q$0$clock;
    reg  [15:0] y_q$1$d;
    wire  [15:0] y_q$1$q;
    reg  y_q$1$clock;
    reg  [15:0] y_q$2$d;
    wire  [15:0] y_q$2$q;
    reg  y_q$2$clock;
    reg  [15:0] y_q$3$d;
    wire  [15:0] y_q$3$q;
    reg  y_q$3$clock;
    reg  [15:0] y_q$4$d;
    wire  [15:0] y_q$4$q;
    reg  y_q$4$clock;
    reg  [15:0] y_q$5$d;
    wire  [15:0] y_q$5$q;
    reg  y_q$5$clock;
    reg  [15:0] y_q$6$d;
    wire  [15:0] y_q$6$q;
    reg  y_q$6$clock;
    reg  [15:0] y_q$7$d;
    wire  [15:0] y_q$7$q;
    reg  y_q$7$clock;
    reg  [15:0] y_q$8$d;
    wire  [15:0] y_q$8$q;
    reg  y_q$8$clock;
    reg  sr_q$0$d;
    wire  sr_q$0$q;
    reg  sr_q$0$clock;
    reg  sr_q$1$d;
    wire  sr_q$1$q;
    reg  sr_q$1$clock;
    reg  sr_q$2$d;
    wire  sr_q$2$q;
    reg  sr_q$2$clock;
    reg  sr_q$3$d;
    wire  sr_q$3$q;
    reg  sr_q$3$clock;
    reg  sr_q$4$d;
    wire  sr_q$4$q;
    reg  sr_q$4$clock;
    reg  sr_q$5$d;
    wire  sr_q$5$q;
    reg  sr_q$5$clock;
    reg  sr_q$6$d;
    wire  sr_q$6$q;
    reg  sr_q$6$clock;
    reg  sr_q$7$d;
    wire  sr_q$7$q;
    reg  sr_q$7$clock;
    reg  sr_q$8$d;
    wire  sr_q$8$q;
    reg  sr_q$8$clock;
    reg  dxn_q$0$d;
    wire  dxn_q$0$q;
    reg  dxn_q$0$clock;
    reg  dxn_q$1$d;
    wire  dxn_q$1$q;
    reg  dxn_q$1$clock;
    reg  dxn_q$2$d;
    wire  dxn_q$2$q;
    reg  dxn_q$2$clock;
    reg  dxn_q$3$d;
    wire  dxn_q$3$q;
    reg  dxn_q$3$clock;
    reg  dxn_q$4$d;
    wire  dxn_q$4$q;
    reg  dxn_q$4$clock;
    reg  dxn_q$5$d;
    wire  dxn_q$5$q;
    reg  dxn_q$5$clock;
    reg  dxn_q$6$d;
    wire  dxn_q$6$q;
    reg  dxn_q$6$clock;
    reg  dxn_q$7$d;
    wire  dxn_q$7$q;
    reg  dxn_q$7$clock;
    reg  dxn_q$8$d;
    wire  dxn_q$8$q;
    reg  dxn_q$8$clock;
    reg  [15:0] dxm_q$0$d;
    wire  [15:0] dxm_q$0$q;
    reg  dxm_q$0$clock;
    reg  [15:0] dxm_q$1$d;
    wire  [15:0] dxm_q$1$q;
    reg  dxm_q$1$clock;
    reg  [15:0] dxm_q$2$d;
    wire  [15:0] dxm_q$2$q;
    reg  dxm_q$2$clock;
    reg  [15:0] dxm_q$3$d;
    wire  [15:0] dxm_q$3$q;
    reg  dxm_q$3$clock;
    reg  [15:0] dxm_q$4$d;
    wire  [15:0] dxm_q$4$q;
    reg  dxm_q$4$clock;
    reg  [15:0] dxm_q$5$d;
    wire  [15:0] dxm_q$5$q;
    reg  dxm_q$5$clock;
    reg  [15:0] dxm_q$6$d;
    wire  [15:0] dxm_q$6$q;
    reg  dxm_q$6$clock;
    reg  [15:0] dxm_q$7$d;
    wire  [15:0] dxm_q$7$q;
    reg  dxm_q$7$clock;
    reg  [15:0] dxm_q$8$d;
    wire  [15:0] dxm_q$8$q;
    reg  dxm_q$8$clock;
    reg  [15:0] dxm_q$9$d;
    wire  [15:0] dxm_q$9$q;
    reg  dxm_q$9$clock;
    reg  dyn_q$0$d;
    wire  dyn_q$0$q;
    reg  dyn_q$0$clock;
    reg  dyn_q$1$d;
    wire  dyn_q$1$q;
    reg  dyn_q$1$clock;
    reg  dyn_q$2$d;
    wire  dyn_q$2$q;
    reg  dyn_q$2$clock;
    reg  dyn_q$3$d;
    wire  dyn_q$3$q;
    reg  dyn_q$3$clock;
    reg  dyn_q$4$d;
    wire  dyn_q$4$q;
    reg  dyn_q$4$clock;
    reg  dyn_q$5$d;
    wire  dyn_q$5$q;
    reg  dyn_q$5$clock;
    reg  dyn_q$6$d;
    wire  dyn_q$6$q;
    reg  dyn_q$6$clock;
    reg  dyn_q$7$d;
    wire  dyn_q$7$q;
    reg  dyn_q$7$clock;
    reg  dyn_q$8$d;
    wire  dyn_q$8$q;
    reg  dyn_q$8$clock;
    reg  [15:0] dym_q$0$d;
    wire  [15:0] dym_q$0$q;
    reg  dym_q$0$clock;
    reg  [15:0] dym_q$1$d;
    wire  [15:0] dym_q$1$q;
    reg  dym_q$1$clock;
    reg  [15:0] dym_q$2$d;
    wire  [15:0] dym_q$2$q;
    reg  dym_q$2$clock;
    reg  [15:0] dym_q$3$d;
    wire  [15:0] dym_q$3$q;
    reg  dym_q$3$clock;
    reg  [15:0] dym_q$4$d;
    wire  [15:0] dym_q$4$q;
    reg  dym_q$4$clock;
    reg  [15:0] dym_q$5$d;
    wire  [15:0] dym_q$5$q;
    reg  dym_q$5$clock;
    reg  [15:0] dym_q$6$d;
    wire  [15:0] dym_q$6$q;
    reg  dym_q$6$clock;
    reg  [15:0] dym_q$7$d;
    wire  [15:0] dym_q$7$q;
    reg  dym_q$7$clock;
    reg  [15:0] dym_q$8$d;
    wire  [15:0] dym_q$8$q;
    reg  dym_q$8$clock;
    reg  [15:0] dym_q$9$d;
    wire  [15:0] dym_q$9$q;
    reg  dym_q$9$clock;
    reg  v_q$0$d;
    wire  v_q$0$q;
    reg  v_q$0$clock;
    reg  v_q$1$d;
    wire  v_q$1$q;
    reg  v_q$1$clock;
    reg  v_q$2$d;
    wire  v_q$2$q;
    reg  v_q$2$clock;
    reg  v_q$3$d;
    wire  v_q$3$q;
    reg  v_q$3$clock;
    reg  v_q$4$d;
    wire  v_q$4$q;
    reg  v_q$4$clock;
    reg  v_q$5$d;
    wire  v_q$5$q;
    reg  v_q$5$clock;
    reg  v_q$6$d;
    wire  v_q$6$q;
    reg  v_q$6$clock;
    reg  v_q$7$d;
    wire  v_q$7$q;
    reg  v_q$7$clock;
    reg  v_q$8$d;
    wire  v_q$8$q;
    reg  v_q$8$clock;
    reg  v_q$9$d;
    wire  v_q$9$q;
    reg  v_q$9$clock;
    reg  v_q$10$d;
    wire  v_q$10$q;
    reg  v_q$10$clock;
    reg  v_q$11$d;
    wire  v_q$11$q;
    reg  v_q$11$clock;
    reg  v_q$12$d;
    wire  v_q$12$q;
    reg  v_q$12$clock;
    reg  v_q$13$d;
    wire  v_q$13$q;
    reg  v_q$13$clock;
    reg  v_q$14$d;
    wire  v_q$14$q;
    reg  v_q$14$clock;
    reg  v_q$15$d;
    wire  v_q$15$q;
    reg  v_q$15$clock;
    reg  v_q$16$d;
    wire  v_q$16$q;
    reg  v_q$16$clock;
    reg  v_q$17$d;
    wire  v_q$17$q;
    reg  v_q$17$clock;
    reg  v_q$18$d;
    wire  v_q$18$q;
    reg  v_q$18$clock;
    reg  v_q$19$d;
    wire  v_q$19$q;
    reg  v_q$19$clock;
    reg  v_q$20$d;
    wire  v_q$20$q;
    reg  v_q$20$clock;
    reg  er_q$0$d;
    wire  er_q$0$q;
    reg  er_q$0$clock;
    reg  er_q$1$d;
    wire  er_q$1$q;
    reg  er_q$1$clock;
    reg  er_q$2$d;
    wire  er_q$2$q;
    reg  er_q$2$clock;
    reg  er_q$3$d;
    wire  er_q$3$q;
    reg  er_q$3$clock;
    reg  er_q$4$d;
    wire  er_q$4$q;
    reg  er_q$4$clock;
    reg  er_q$5$d;
    wire  er_q$5$q;
    reg  er_q$5$clock;
    reg  er_q$6$d;
    wire  er_q$6$q;
    reg  er_q$6$clock;
    reg  er_q$7$d;
    wire  er_q$7$q;
    reg  er_q$7$clock;
    reg  er_q$8$d;
    wire  er_q$8$q;
    reg  er_q$8$clock;
    reg  er_q$9$d;
    wire  er_q$9$q;
    reg  er_q$9$clock;
    reg  er_q$10$d;
    wire  er_q$10$q;
    reg  er_q$10$clock;
    reg  er_q$11$d;
    wire  er_q$11$q;
    reg  er_q$11$clock;
    reg  er_q$12$d;
    wire  er_q$12$q;
    reg  er_q$12$clock;
    reg  er_q$13$d;
    wire  er_q$13$q;
    reg  er_q$13$clock;
    reg  er_q$14$d;
    wire  er_q$14$q;
    reg  er_q$14$clock;
    reg  er_q$15$d;
    wire  er_q$15$q;
    reg  er_q$15$clock;
    reg  er_q$16$d;
    wire  er_q$16$q;
    reg  er_q$16$clock;
    reg  er_q$17$d;
    wire  er_q$17$q;
    reg  er_q$17$clock;
    reg  er_q$18$d;
    wire  er_q$18$q;
    reg  er_q$18$clock;
    reg  er_q$19$d;
    wire  er_q$19$q;
    reg  er_q$19$clock;
    reg  er_q$20$d;
    wire  er_q$20$q;
    reg  er_q$20$clock;
    reg  pad_q$0$d;
    wire  pad_q$0$q;
    reg  pad_q$0$clock;
    reg  pad_q$1$d;
    wire  pad_q$1$q;
    reg  pad_q$1$clock;
    reg  pad_q$2$d;
    wire  pad_q$2$q;
    reg  pad_q$2$clock;
    reg  pad_q$3$d;
    wire  pad_q$3$q;
    reg  pad_q$3$clock;
    reg  pad_q$4$d;
    wire  pad_q$4$q;
    reg  pad_q$4$clock;
    reg  pad_q$5$d;
    wire  pad_q$5$q;
    reg  pad_q$5$clock;
    reg  pad_q$6$d;
    wire  pad_q$6$q;
    reg  pad_q$6$clock;
    reg  pad_q$7$d;
    wire  pad_q$7$q;
    reg  pad_q$7$clock;
    reg  pad_q$8$d;
    wire  pad_q$8$q;
    reg  pad_q$8$clock;
    reg  pad_q$9$d;
    wire  pad_q$9$q;
    reg  pad_q$9$clock;
    reg  pad_q$10$d;
    wire  pad_q$10$q;
    reg  pad_q$10$clock;
    reg  pad_q$11$d;
    wire  pad_q$11$q;
    reg  pad_q$11$clock;
    reg  pad_q$12$d;
    wire  pad_q$12$q;
    reg  pad_q$12$clock;
    reg  pad_q$13$d;
    wire  pad_q$13$q;
    reg  pad_q$13$clock;
    reg  pad_q$14$d;
    wire  pad_q$14$q;
    reg  pad_q$14$clock;
    reg  pad_q$15$d;
    wire  pad_q$15$q;
    reg  pad_q$15$clock;
    reg  pad_q$16$d;
    wire  pad_q$16$q;
    reg  pad_q$16$clock;
    reg  pad_q$17$d;
    wire  pad_q$17$q;
    reg  pad_q$17$clock;
    reg  pad_q$18$d;
    wire  pad_q$18$q;
    reg  pad_q$18$clock;
    reg  pad_q$19$d;
    wire  pad_q$19$q;
    reg  pad_q$19$clock;
    reg  pad_q$20$d;
    wire  pad_q$20$q;
    reg  pad_q$20$clock;
    reg  [15:0] bx_q$0$d;
    wire  [15:0] bx_q$0$q;
    reg  bx_q$0$clock;
    reg  [15:0] bx_q$1$d;
    wire  [15:0] bx_q$1$q;
    reg  bx_q$1$clock;
    reg  [15:0] bx_q$2$d;
    wire  [15:0] bx_q$2$q;
    reg  bx_q$2$clock;
    reg  [15:0] bx_q$3$d;
    wire  [15:0] bx_q$3$q;
    reg  bx_q$3$clock;
    reg  [15:0] bx_q$4$d;
    wire  [15:0] bx_q$4$q;
    reg  bx_q$4$clock;
    reg  [15:0] bx_q$5$d;
    wire  [15:0] bx_q$5$q;
    reg  bx_q$5$clock;
    reg  [15:0] bx_q$6$d;
    wire  [15:0] bx_q$6$q;
    reg  bx_q$6$clock;
    reg  [15:0] bx_q$7$d;
    wire  [15:0] bx_q$7$q;
    reg  bx_q$7$clock;
    reg  [15:0] bx_q$8$d;
    wire  [15:0] bx_q$8$q;
    reg  bx_q$8$clock;
    reg  [15:0] bx_q$9$d;
    wire  [15:0] bx_q$9$q;
    reg  bx_q$9$clock;
    reg  [15:0] bx_q$10$d;
    wire  [15:0] bx_q$10$q;
    reg  bx_q$10$clock;
    reg  [15:0] bx_q$11$d;
    wire  [15:0] bx_q$11$q;
    reg  bx_q$11$clock;
    reg  [15:0] bx_q$12$d;
    wire  [15:0] bx_q$12$q;
    reg  bx_q$12$clock;
    reg  [15:0] bx_q$13$d;
    wire  [15:0] bx_q$13$q;
    reg  bx_q$13$clock;
    reg  [15:0] bx_q$14$d;
    wire  [15:0] bx_q$14$q;
    reg  bx_q$14$clock;
    reg  [15:0] bx_q$15$d;
    wire  [15:0] bx_q$15$q;
    reg  bx_q$15$clock;
    reg  [15:0] bx_q$16$d;
    wire  [15:0] bx_q$16$q;
    reg  bx_q$16$clock;
    reg  [15:0] bx_q$17$d;
    wire  [15:0] bx_q$17$q;
    reg  bx_q$17$clock;
    reg  [15:0] bx_q$18$d;
    wire  [15:0] bx_q$18$q;
    reg  bx_q$18$clock;
    reg  [15:0] bx_q$19$d;
    wire  [15:0] bx_q$19$q;
    reg  bx_q$19$clock;
    reg  [15:0] bx_q$20$d;
    wire  [15:0] bx_q$20$q;
    reg  bx_q$20$clock;
    reg  [15:0] by_q$0$d;
    wire  [15:0] by_q$0$q;
    reg  by_q$0$clock;
    reg  [15:0] by_q$1$d;
    wire  [15:0] by_q$1$q;
    reg  by_q$1$clock;
    reg  [15:0] by_q$2$d;
    wire  [15:0] by_q$2$q;
    reg  by_q$2$clock;
    reg  [15:0] by_q$3$d;
    wire  [15:0] by_q$3$q;
    reg  by_q$3$clock;
    reg  [15:0] by_q$4$d;
    wire  [15:0] by_q$4$q;
    reg  by_q$4$clock;
    reg  [15:0] by_q$5$d;
    wire  [15:0] by_q$5$q;
    reg  by_q$5$clock;
    reg  [15:0] by_q$6$d;
    wire  [15:0] by_q$6$q;
    reg  by_q$6$clock;
    reg  [15:0] by_q$7$d;
    wire  [15:0] by_q$7$q;
    reg  by_q$7$clock;
    reg  [15:0] by_q$8$d;
    wire  [15:0] by_q$8$q;
    reg  by_q$8$clock;
    reg  [15:0] by_q$9$d;
    wire  [15:0] by_q$9$q;
    reg  by_q$9$clock;
    reg  [15:0] by_q$10$d;
    wire  [15:0] by_q$10$q;
    reg  by_q$10$clock;
    reg  [15:0] by_q$11$d;
    wire  [15:0] by_q$11$q;
    reg  by_q$11$clock;
    reg  [15:0] by_q$12$d;
    wire  [15:0] by_q$12$q;
    reg  by_q$12$clock;
    reg  [15:0] by_q$13$d;
    wire  [15:0] by_q$13$q;
    reg  by_q$13$clock;
    reg  [15:0] by_q$14$d;
    wire  [15:0] by_q$14$q;
    reg  by_q$14$clock;
    reg  [15:0] by_q$15$d;
    wire  [15:0] by_q$15$q;
    reg  by_q$15$clock;
    reg  [15:0] by_q$16$d;
    wire  [15:0] by_q$16$q;
    reg  by_q$16$clock;
    reg  [15:0] by_q$17$d;
    wire  [15:0] by_q$17$q;
    reg  by_q$17$clock;
    reg  [15:0] by_q$18$d;
    wire  [15:0] by_q$18$q;
    reg  by_q$18$clock;
    reg  [15:0] by_q$19$d;
    wire  [15:0] by_q$19$q;
    reg  by_q$19$clock;
    reg  [15:0] by_q$20$d;
    wire  [15:0] by_q$20$q;
    reg  by_q$20$clock;
    reg  [2:0] face_q$0$d;
    wire  [2:0] face_q$0$q;
    reg  face_q$0$clock;
    reg  [2:0] face_q$1$d;
    wire  [2:0] face_q$1$q;
    reg  face_q$1$clock;
    reg  [2:0] face_q$2$d;
    wire  [2:0] face_q$2$q;
    reg  face_q$2$clock;
    reg  [2:0] face_q$3$d;
    wire  [2:0] face_q$3$q;
    reg  face_q$3$clock;
    reg  [2:0] face_q$4$d;
    wire  [2:0] face_q$4$q;
    reg  face_q$4$clock;
    reg  [2:0] face_q$5$d;
    wire  [2:0] face_q$5$q;
    reg  face_q$5$clock;
    reg  [2:0] face_q$6$d;
    wire  [2:0] face_q$6$q;
    reg  face_q$6$clock;
    reg  [2:0] face_q$7$d;
    wire  [2:0] face_q$7$q;
    reg  face_q$7$clock;
    reg  [2:0] face_q$8$d;
    wire  [2:0] face_q$8$q;
    reg  face_q$8$clock;
    reg  [2:0] face_q$9$d;
    wire  [2:0] face_q$9$q;
    reg  face_q$9$clock;
    reg  [2:0] face_q$10$d;
    wire  [2:0] face_q$10$q;
    reg  face_q$10$clock;
    reg  [2:0] face_q$11$d;
    wire  [2:0] face_q$11$q;
    reg  face_q$11$clock;
    reg  [2:0] face_q$12$d;
    wire  [2:0] face_q$12$q;
    reg  face_q$12$clock;
    reg  [2:0] face_q$13$d;
    wire  [2:0] face_q$13$q;
    reg  face_q$13$clock;
    reg  [2:0] face_q$14$d;
    wire  [2:0] face_q$14$q;
    reg  face_q$14$clock;
    reg  [2:0] face_q$15$d;
    wire  [2:0] face_q$15$q;
    reg  face_q$15$clock;
    reg  [2:0] face_q$16$d;
    wire  [2:0] face_q$16$q;
    reg  face_q$16$clock;
    reg  [2:0] face_q$17$d;
    wire  [2:0] face_q$17$q;
    reg  face_q$17$clock;
    reg  [2:0] face_q$18$d;
    wire  [2:0] face_q$18$q;
    reg  face_q$18$clock;
    reg  [2:0] face_q$19$d;
    wire  [2:0] face_q$19$q;
    reg  face_q$19$clock;
    reg  [2:0] face_q$20$d;
    wire  [2:0] face_q$20$q;
    reg  face_q$20$clock;
    
    // Local signals
    reg  x_out;
    reg  y_out;
    reg  dx_nz;
    reg  dy_nz;
    reg  [6:0] sel;
    
    // Sub module instances
    top$lanes$2$ctl$nx_last nx_last(
        .d(nx_last$d),
        .q(nx_last$q),
        .clock(nx_last$clock)
    );
    top$lanes$2$ctl$ny_last ny_last(
        .d(ny_last$d),
        .q(ny_last$q),
        .clock(ny_last$clock)
    );
    top$lanes$2$ctl$sel_q$0 sel_q$0(
        .d(sel_q$0$d),
        .q(sel_q$0$q),
        .clock(sel_q$0$clock)
    );
    top$lanes$2$ctl$sel_q$1 sel_q$1(
        .d(sel_q$1$d),
        .q(sel_q$1$q),
        .clock(sel_q$1$clock)
    );
    top$lanes$2$ctl$sel_q$2 sel_q$2(
        .d(sel_q$2$d),
        .q(sel_q$2$q),
        .clock(sel_q$2$clock)
    );
    top$lanes$2$ctl$sel_q$3 sel_q$3(
        .d(sel_q$3$d),
        .q(sel_q$3$q),
        .clock(sel_q$3$clock)
    );
    top$lanes$2$ctl$x_q$0 x_q$0(
        .d(x_q$0$d),
        .q(x_q$0$q),
        .clock(x_q$0$clock)
    );
    top$lanes$2$ctl$x_q$1 x_q$1(
        .d(x_q$1$d),
        .q(x_q$1$q),
        .clock(x_q$1$clock)
    );
    top$lanes$2$ctl$x_q$2 x_q$2(
        .d(x_q$2$d),
        .q(x_q$2$q),
        .clock(x_q$2$clock)
    );
    top$lanes$2$ctl$x_q$3 x_q$3(
        .d(x_q$3$d),
        .q(x_q$3$q),
        .clock(x_q$3$clock)
    );
    top$lanes$2$ctl$x_q$4 x_q$4(
        .d(x_q$4$d),
        .q(x_q$4$q),
        .clock(x_q$4$clock)
    );
    top$lanes$2$ctl$x_q$5 x_q$5(
        .d(x_q$5$d),
        .q(x_q$5$q),
        .clock(x_q$5$clock)
    );
    top$lanes$2$ctl$x_q$6 x_q$6(
        .d(x_q$6$d),
        .q(x_q$6$q),
        .clock(x_q$6$clock)
    );
    top$lanes$2$ctl$x_q$7 x_q$7(
        .d(x_q$7$d),
        .q(x_q$7$q),
        .clock(x_q$7$clock)
    );
    top$lanes$2$ctl$x_q$8 x_q$8(
        .d(x_q$8$d),
        .q(x_q$8$q),
        .clock(x_q$8$clock)
    );
    top$lanes$2$ctl$x_q$9 x_q$9(
        .d(x_q$9$d),
        .q(x_q$9$q),
        .clock(x_q$9$clock)
    );
    top$lanes$2$ctl$y_q$0 y_q$0(
        .d(y_q$0$d),
        .q(y_q$0$q),
        .clock(y_q$0$clock)
    );
    top$lanes$2$ctl$y_q$1 y_q$1(
        .d(y_q$1$d),
        .q(y_q$1$q),
        .clock(y_q$1$clock)
    );
    top$lanes$2$ctl$y_q$2 y_q$2(
        .d(y_q$2$d),
        .q(y_q$2$q),
        .clock(y_q$2$clock)
    );
    top$lanes$2$ctl$y_q$3 y_q$3(
        .d(y_q$3$d),
        .q(y_q$3$q),
        .clock(y_q$3$clock)
    );
    top$lanes$2$ctl$y_q$4 y_q$4(
        .d(y_q$4$d),
        .q(y_q$4$q),
        .clock(y_q$4$clock)
    );
    top$lanes$2$ctl$y_q$5 y_q$5(
        .d(y_q$5$d),
        .q(y_q$5$q),
        .clock(y_q$5$clock)
    );
    top$lanes$2$ctl$y_q$6 y_q$6(
        .d(y_q$6$d),
        .q(y_q$6$q),
        .clock(y_q$6$clock)
    );
    top$lanes$2$ctl$y_q$7 y_q$7(
        .d(y_q$7$d),
        .q(y_q$7$q),
        .clock(y_q$7$clock)
    );
    top$lanes$2$ctl$y_q$8 y_q$8(
        .d(y_q$8$d),
        .q(y_q$8$q),
        .clock(y_q$8$clock)
    );
    top$lanes$2$ctl$sr_q$0 sr_q$0(
        .d(sr_q$0$d),
        .q(sr_q$0$q),
        .clock(sr_q$0$clock)
    );
    top$lanes$2$ctl$sr_q$1 sr_q$1(
        .d(sr_q$1$d),
        .q(sr_q$1$q),
        .clock(sr_q$1$clock)
    );
    top$lanes$2$ctl$sr_q$2 sr_q$2(
        .d(sr_q$2$d),
        .q(sr_q$2$q),
        .clock(sr_q$2$clock)
    );
    top$lanes$2$ctl$sr_q$3 sr_q$3(
        .d(sr_q$3$d),
        .q(sr_q$3$q),
        .clock(sr_q$3$clock)
    );
    top$lanes$2$ctl$sr_q$4 sr_q$4(
        .d(sr_q$4$d),
        .q(sr_q$4$q),
        .clock(sr_q$4$clock)
    );
    top$lanes$2$ctl$sr_q$5 sr_q$5(
        .d(sr_q$5$d),
        .q(sr_q$5$q),
        .clock(sr_q$5$clock)
    );
    top$lanes$2$ctl$sr_q$6 sr_q$6(
        .d(sr_q$6$d),
        .q(sr_q$6$q),
        .clock(sr_q$6$clock)
    );
    top$lanes$2$ctl$sr_q$7 sr_q$7(
        .d(sr_q$7$d),
        .q(sr_q$7$q),
        .clock(sr_q$7$clock)
    );
    top$lanes$2$ctl$sr_q$8 sr_q$8(
        .d(sr_q$8$d),
        .q(sr_q$8$q),
        .clock(sr_q$8$clock)
    );
    top$lanes$2$ctl$dxn_q$0 dxn_q$0(
        .d(dxn_q$0$d),
        .q(dxn_q$0$q),
        .clock(dxn_q$0$clock)
    );
    top$lanes$2$ctl$dxn_q$1 dxn_q$1(
        .d(dxn_q$1$d),
        .q(dxn_q$1$q),
        .clock(dxn_q$1$clock)
    );
    top$lanes$2$ctl$dxn_q$2 dxn_q$2(
        .d(dxn_q$2$d),
        .q(dxn_q$2$q),
        .clock(dxn_q$2$clock)
    );
    top$lanes$2$ctl$dxn_q$3 dxn_q$3(
        .d(dxn_q$3$d),
        .q(dxn_q$3$q),
        .clock(dxn_q$3$clock)
    );
    top$lanes$2$ctl$dxn_q$4 dxn_q$4(
        .d(dxn_q$4$d),
        .q(dxn_q$4$q),
        .clock(dxn_q$4$clock)
    );
    top$lanes$2$ctl$dxn_q$5 dxn_q$5(
        .d(dxn_q$5$d),
        .q(dxn_q$5$q),
        .clock(dxn_q$5$clock)
    );
    top$lanes$2$ctl$dxn_q$6 dxn_q$6(
        .d(dxn_q$6$d),
        .q(dxn_q$6$q),
        .clock(dxn_q$6$clock)
    );
    top$lanes$2$ctl$dxn_q$7 dxn_q$7(
        .d(dxn_q$7$d),
        .q(dxn_q$7$q),
        .clock(dxn_q$7$clock)
    );
    top$lanes$2$ctl$dxn_q$8 dxn_q$8(
        .d(dxn_q$8$d),
        .q(dxn_q$8$q),
        .clock(dxn_q$8$clock)
    );
    top$lanes$2$ctl$dxm_q$0 dxm_q$0(
        .d(dxm_q$0$d),
        .q(dxm_q$0$q),
        .clock(dxm_q$0$clock)
    );
    top$lanes$2$ctl$dxm_q$1 dxm_q$1(
        .d(dxm_q$1$d),
        .q(dxm_q$1$q),
        .clock(dxm_q$1$clock)
    );
    top$lanes$2$ctl$dxm_q$2 dxm_q$2(
        .d(dxm_q$2$d),
        .q(dxm_q$2$q),
        .clock(dxm_q$2$clock)
    );
    top$lanes$2$ctl$dxm_q$3 dxm_q$3(
        .d(dxm_q$3$d),
        .q(dxm_q$3$q),
        .clock(dxm_q$3$clock)
    );
    top$lanes$2$ctl$dxm_q$4 dxm_q$4(
        .d(dxm_q$4$d),
        .q(dxm_q$4$q),
        .clock(dxm_q$4$clock)
    );
    top$lanes$2$ctl$dxm_q$5 dxm_q$5(
        .d(dxm_q$5$d),
        .q(dxm_q$5$q),
        .clock(dxm_q$5$clock)
    );
    top$lanes$2$ctl$dxm_q$6 dxm_q$6(
        .d(dxm_q$6$d),
        .q(dxm_q$6$q),
        .clock(dxm_q$6$clock)
    );
    top$lanes$2$ctl$dxm_q$7 dxm_q$7(
        .d(dxm_q$7$d),
        .q(dxm_q$7$q),
        .clock(dxm_q$7$clock)
    );
    top$lanes$2$ctl$dxm_q$8 dxm_q$8(
        .d(dxm_q$8$d),
        .q(dxm_q$8$q),
        .clock(dxm_q$8$clock)
    );
    top$lanes$2$ctl$dxm_q$9 dxm_q$9(
        .d(dxm_q$9$d),
        .q(dxm_q$9$q),
        .clock(dxm_q$9$clock)
    );
    top$lanes$2$ctl$dyn_q$0 dyn_q$0(
        .d(dyn_q$0$d),
        .q(dyn_q$0$q),
        .clock(dyn_q$0$clock)
    );
    top$lanes$2$ctl$dyn_q$1 dyn_q$1(
        .d(dyn_q$1$d),
        .q(dyn_q$1$q),
        .clock(dyn_q$1$clock)
    );
    top$lanes$2$ctl$dyn_q$2 dyn_q$2(
        .d(dyn_q$2$d),
        .q(dyn_q$2$q),
        .clock(dyn_q$2$clock)
    );
    top$lanes$2$ctl$dyn_q$3 dyn_q$3(
        .d(dyn_q$3$d),
        .q(dyn_q$3$q),
        .clock(dyn_q$3$clock)
    );
    top$lanes$2$ctl$dyn_q$4 dyn_q$4(
        .d(dyn_q$4$d),
        .q(dyn_q$4$q),
        .clock(dyn_q$4$clock)
    );
    top$lanes$2$ctl$dyn_q$5 dyn_q$5(
        .d(dyn_q$5$d),
        .q(dyn_q$5$q),
        .clock(dyn_q$5$clock)
    );
    top$lanes$2$ctl$dyn_q$6 dyn_q$6(
        .d(dyn_q$6$d),
        .q(dyn_q$6$q),
        .clock(dyn_q$6$clock)
    );
    top$lanes$2$ctl$dyn_q$7 dyn_q$7(
        .d(dyn_q$7$d),
        .q(dyn_q$7$q),
        .clock(dyn_q$7$clock)
    );
    top$lanes$2$ctl$dyn_q$8 dyn_q$8(
        .d(dyn_q$8$d),
        .q(dyn_q$8$q),
        .clock(dyn_q$8$clock)
    );
    top$lanes$2$ctl$dym_q$0 dym_q$0(
        .d(dym_q$0$d),
        .q(dym_q$0$q),
        .clock(dym_q$0$clock)
    );
    top$lanes$2$ctl$dym_q$1 dym_q$1(
        .d(dym_q$1$d),
        .q(dym_q$1$q),
        .clock(dym_q$1$clock)
    );
    top$lanes$2$ctl$dym_q$2 dym_q$2(
        .d(dym_q$2$d),
        .q(dym_q$2$q),
        .clock(dym_q$2$clock)
    );
    top$lanes$2$ctl$dym_q$3 dym_q$3(
        .d(dym_q$3$d),
        .q(dym_q$3$q),
        .clock(dym_q$3$clock)
    );
    top$lanes$2$ctl$dym_q$4 dym_q$4(
        .d(dym_q$4$d),
        .q(dym_q$4$q),
        .clock(dym_q$4$clock)
    );
    top$lanes$2$ctl$dym_q$5 dym_q$5(
        .d(dym_q$5$d),
        .q(dym_q$5$q),
        .clock(dym_q$5$clock)
    );
    top$lanes$2$ctl$dym_q$6 dym_q$6(
        .d(dym_q$6$d),
        .q(dym_q$6$q),
        .clock(dym_q$6$clock)
    );
    top$lanes$2$ctl$dym_q$7 dym_q$7(
        .d(dym_q$7$d),
        .q(dym_q$7$q),
        .clock(dym_q$7$clock)
    );
    top$lanes$2$ctl$dym_q$8 dym_q$8(
        .d(dym_q$8$d),
        .q(dym_q$8$q),
        .clock(dym_q$8$clock)
    );
    top$lanes$2$ctl$dym_q$9 dym_q$9(
        .d(dym_q$9$d),
        .q(dym_q$9$q),
        .clock(dym_q$9$clock)
    );
    top$lanes$2$ctl$v_q$0 v_q$0(
        .d(v_q$0$d),
        .q(v_q$0$q),
        .clock(v_q$0$clock)
    );
    top$lanes$2$ctl$v_q$1 v_q$1(
        .d(v_q$1$d),
        .q(v_q$1$q),
        .clock(v_q$1$clock)
    );
    top$lanes$2$ctl$v_q$2 v_q$2(
        .d(v_q$2$d),
        .q(v_q$2$q),
        .clock(v_q$2$clock)
    );
    top$lanes$2$ctl$v_q$3 v_q$3(
        .d(v_q$3$d),
        .q(v_q$3$q),
        .clock(v_q$3$clock)
    );
    top$lanes$2$ctl$v_q$4 v_q$4(
        .d(v_q$4$d),
        .q(v_q$4$q),
        .clock(v_q$4$clock)
    );
    top$lanes$2$ctl$v_q$5 v_q$5(
        .d(v_q$5$d),
        .q(v_q$5$q),
        .clock(v_q$5$clock)
    );
    top$lanes$2$ctl$v_q$6 v_q$6(
        .d(v_q$6$d),
        .q(v_q$6$q),
        .clock(v_q$6$clock)
    );
    top$lanes$2$ctl$v_q$7 v_q$7(
        .d(v_q$7$d),
        .q(v_q$7$q),
        .clock(v_q$7$clock)
    );
    top$lanes$2$ctl$v_q$8 v_q$8(
        .d(v_q$8$d),
        .q(v_q$8$q),
        .clock(v_q$8$clock)
    );
    top$lanes$2$ctl$v_q$9 v_q$9(
        .d(v_q$9$d),
        .q(v_q$9$q),
        .clock(v_q$9$clock)
    );
    top$lanes$2$ctl$v_q$10 v_q$10(
        .d(v_q$10$d),
        .q(v_q$10$q),
        .clock(v_q$10$clock)
    );
    top$lanes$2$ctl$v_q$11 v_q$11(
        .d(v_q$11$d),
        .q(v_q$11$q),
        .clock(v_q$11$clock)
    );
    top$lanes$2$ctl$v_q$12 v_q$12(
        .d(v_q$12$d),
        .q(v_q$12$q),
        .clock(v_q$12$clock)
    );
    top$lanes$2$ctl$v_q$13 v_q$13(
        .d(v_q$13$d),
        .q(v_q$13$q),
        .clock(v_q$13$clock)
    );
    top$lanes$2$ctl$v_q$14 v_q$14(
        .d(v_q$14$d),
        .q(v_q$14$q),
        .clock(v_q$14$clock)
    );
    top$lanes$2$ctl$v_q$15 v_q$15(
        .d(v_q$15$d),
        .q(v_q$15$q),
        .clock(v_q$15$clock)
    );
    top$lanes$2$ctl$v_q$16 v_q$16(
        .d(v_q$16$d),
        .q(v_q$16$q),
        .clock(v_q$16$clock)
    );
    top$lanes$2$ctl$v_q$17 v_q$17(
        .d(v_q$17$d),
        .q(v_q$17$q),
        .clock(v_q$17$clock)
    );
    top$lanes$2$ctl$v_q$18 v_q$18(
        .d(v_q$18$d),
        .q(v_q$18$q),
        .clock(v_q$18$clock)
    );
    top$lanes$2$ctl$v_q$19 v_q$19(
        .d(v_q$19$d),
        .q(v_q$19$q),
        .clock(v_q$19$clock)
    );
    top$lanes$2$ctl$v_q$20 v_q$20(
        .d(v_q$20$d),
        .q(v_q$20$q),
        .clock(v_q$20$clock)
    );
    top$lanes$2$ctl$er_q$0 er_q$0(
        .d(er_q$0$d),
        .q(er_q$0$q),
        .clock(er_q$0$clock)
    );
    top$lanes$2$ctl$er_q$1 er_q$1(
        .d(er_q$1$d),
        .q(er_q$1$q),
        .clock(er_q$1$clock)
    );
    top$lanes$2$ctl$er_q$2 er_q$2(
        .d(er_q$2$d),
        .q(er_q$2$q),
        .clock(er_q$2$clock)
    );
    top$lanes$2$ctl$er_q$3 er_q$3(
        .d(er_q$3$d),
        .q(er_q$3$q),
        .clock(er_q$3$clock)
    );
    top$lanes$2$ctl$er_q$4 er_q$4(
        .d(er_q$4$d),
        .q(er_q$4$q),
        .clock(er_q$4$clock)
    );
    top$lanes$2$ctl$er_q$5 er_q$5(
        .d(er_q$5$d),
        .q(er_q$5$q),
        .clock(er_q$5$clock)
    );
    top$lanes$2$ctl$er_q$6 er_q$6(
        .d(er_q$6$d),
        .q(er_q$6$q),
        .clock(er_q$6$clock)
    );
    top$lanes$2$ctl$er_q$7 er_q$7(
        .d(er_q$7$d),
        .q(er_q$7$q),
        .clock(er_q$7$clock)
    );
    top$lanes$2$ctl$er_q$8 er_q$8(
        .d(er_q$8$d),
        .q(er_q$8$q),
        .clock(er_q$8$clock)
    );
    top$lanes$2$ctl$er_q$9 er_q$9(
        .d(er_q$9$d),
        .q(er_q$9$q),
        .clock(er_q$9$clock)
    );
    top$lanes$2$ctl$er_q$10 er_q$10(
        .d(er_q$10$d),
        .q(er_q$10$q),
        .clock(er_q$10$clock)
    );
    top$lanes$2$ctl$er_q$11 er_q$11(
        .d(er_q$11$d),
        .q(er_q$11$q),
        .clock(er_q$11$clock)
    );
    top$lanes$2$ctl$er_q$12 er_q$12(
        .d(er_q$12$d),
        .q(er_q$12$q),
        .clock(er_q$12$clock)
    );
    top$lanes$2$ctl$er_q$13 er_q$13(
        .d(er_q$13$d),
        .q(er_q$13$q),
        .clock(er_q$13$clock)
    );
    top$lanes$2$ctl$er_q$14 er_q$14(
        .d(er_q$14$d),
        .q(er_q$14$q),
        .clock(er_q$14$clock)
    );
    top$lanes$2$ctl$er_q$15 er_q$15(
        .d(er_q$15$d),
        .q(er_q$15$q),
        .clock(er_q$15$clock)
    );
    top$lanes$2$ctl$er_q$16 er_q$16(
        .d(er_q$16$d),
        .q(er_q$16$q),
        .clock(er_q$16$clock)
    );
    top$lanes$2$ctl$er_q$17 er_q$17(
        .d(er_q$17$d),
        .q(er_q$17$q),
        .clock(er_q$17$clock)
    );
    top$lanes$2$ctl$er_q$18 er_q$18(
        .d(er_q$18$d),
        .q(er_q$18$q),
        .clock(er_q$18$clock)
    );
    top$lanes$2$ctl$er_q$19 er_q$19(
        .d(er_q$19$d),
        .q(er_q$19$q),
        .clock(er_q$19$clock)
    );
    top$lanes$2$ctl$er_q$20 er_q$20(
        .d(er_q$20$d),
        .q(er_q$20$q),
        .clock(er_q$20$clock)
    );
    top$lanes$2$ctl$pad_q$0 pad_q$0(
        .d(pad_q$0$d),
        .q(pad_q$0$q),
        .clock(pad_q$0$clock)
    );
    top$lanes$2$ctl$pad_q$1 pad_q$1(
        .d(pad_q$1$d),
        .q(pad_q$1$q),
        .clock(pad_q$1$clock)
    );
    top$lanes$2$ctl$pad_q$2 pad_q$2(
        .d(pad_q$2$d),
        .q(pad_q$2$q),
        .clock(pad_q$2$clock)
    );
    top$lanes$2$ctl$pad_q$3 pad_q$3(
        .d(pad_q$3$d),
        .q(pad_q$3$q),
        .clock(pad_q$3$clock)
    );
    top$lanes$2$ctl$pad_q$4 pad_q$4(
        .d(pad_q$4$d),
        .q(pad_q$4$q),
        .clock(pad_q$4$clock)
    );
    top$lanes$2$ctl$pad_q$5 pad_q$5(
        .d(pad_q$5$d),
        .q(pad_q$5$q),
        .clock(pad_q$5$clock)
    );
    top$lanes$2$ctl$pad_q$6 pad_q$6(
        .d(pad_q$6$d),
        .q(pad_q$6$q),
        .clock(pad_q$6$clock)
    );
    top$lanes$2$ctl$pad_q$7 pad_q$7(
        .d(pad_q$7$d),
        .q(pad_q$7$q),
        .clock(pad_q$7$clock)
    );
    top$lanes$2$ctl$pad_q$8 pad_q$8(
        .d(pad_q$8$d),
        .q(pad_q$8$q),
        .clock(pad_q$8$clock)
    );
    top$lanes$2$ctl$pad_q$9 pad_q$9(
        .d(pad_q$9$d),
        .q(pad_q$9$q),
        .clock(pad_q$9$clock)
    );
    top$lanes$2$ctl$pad_q$10 pad_q$10(
        .d(pad_q$10$d),
        .q(pad_q$10$q),
        .clock(pad_q$10$clock)
    );
    top$lanes$2$ctl$pad_q$11 pad_q$11(
        .d(pad_q$11$d),
        .q(pad_q$11$q),
        .clock(pad_q$11$clock)
    );
    top$lanes$2$ctl$pad_q$12 pad_q$12(
        .d(pad_q$12$d),
        .q(pad_q$12$q),
        .clock(pad_q$12$clock)
    );
    top$lanes$2$ctl$pad_q$13 pad_q$13(
        .d(pad_q$13$d),
        .q(pad_q$13$q),
        .clock(pad_q$13$clock)
    );
    top$lanes$2$ctl$pad_q$14 pad_q$14(
        .d(pad_q$14$d),
        .q(pad_q$14$q),
        .clock(pad_q$14$clock)
    );
    top$lanes$2$ctl$pad_q$15 pad_q$15(
        .d(pad_q$15$d),
        .q(pad_q$15$q),
        .clock(pad_q$15$clock)
    );
    top$lanes$2$ctl$pad_q$16 pad_q$16(
        .d(pad_q$16$d),
        .q(pad_q$16$q),
        .clock(pad_q$16$clock)
    );
    top$lanes$2$ctl$pad_q$17 pad_q$17(
        .d(pad_q$17$d),
        .q(pad_q$17$q),
        .clock(pad_q$17$clock)
    );
    top$lanes$2$ctl$pad_q$18 pad_q$18(
        .d(pad_q$18$d),
        .q(pad_q$18$q),
        .clock(pad_q$18$clock)
    );
    top$lanes$2$ctl$pad_q$19 pad_q$19(
        .d(pad_q$19$d),
        .q(pad_q$19$q),
        .clock(pad_q$19$clock)
    );
    top$lanes$2$ctl$pad_q$20 pad_q$20(
        .d(pad_q$20$d),
        .q(pad_q$20$q),
        .clock(pad_q$20$clock)
    );
    top$lanes$2$ctl$bx_q$0 bx_q$0(
        .d(bx_q$0$d),
        .q(bx_q$0$q),
        .clock(bx_q$0$clock)
    );
    top$lanes$2$ctl$bx_q$1 bx_q$1(
        .d(bx_q$1$d),
        .q(bx_q$1$q),
        .clock(bx_q$1$clock)
    );
    top$lanes$2$ctl$bx_q$2 bx_q$2(
        .d(bx_q$2$d),
        .q(bx_q$2$q),
        .clock(bx_q$2$clock)
    );
    top$lanes$2$ctl$bx_q$3 bx_q$3(
        .d(bx_q$3$d),
        .q(bx_q$3$q),
        .clock(bx_q$3$clock)
    );
    top$lanes$2$ctl$bx_q$4 bx_q$4(
        .d(bx_q$4$d),
        .q(bx_q$4$q),
        .clock(bx_q$4$clock)
    );
    top$lanes$2$ctl$bx_q$5 bx_q$5(
        .d(bx_q$5$d),
        .q(bx_q$5$q),
        .clock(bx_q$5$clock)
    );
    top$lanes$2$ctl$bx_q$6 bx_q$6(
        .d(bx_q$6$d),
        .q(bx_q$6$q),
        .clock(bx_q$6$clock)
    );
    top$lanes$2$ctl$bx_q$7 bx_q$7(
        .d(bx_q$7$d),
        .q(bx_q$7$q),
        .clock(bx_q$7$clock)
    );
    top$lanes$2$ctl$bx_q$8 bx_q$8(
        .d(bx_q$8$d),
        .q(bx_q$8$q),
        .clock(bx_q$8$clock)
    );
    top$lanes$2$ctl$bx_q$9 bx_q$9(
        .d(bx_q$9$d),
        .q(bx_q$9$q),
        .clock(bx_q$9$clock)
    );
    top$lanes$2$ctl$bx_q$10 bx_q$10(
        .d(bx_q$10$d),
        .q(bx_q$10$q),
        .clock(bx_q$10$clock)
    );
    top$lanes$2$ctl$bx_q$11 bx_q$11(
        .d(bx_q$11$d),
        .q(bx_q$11$q),
        .clock(bx_q$11$clock)
    );
    top$lanes$2$ctl$bx_q$12 bx_q$12(
        .d(bx_q$12$d),
        .q(bx_q$12$q),
        .clock(bx_q$12$clock)
    );
    top$lanes$2$ctl$bx_q$13 bx_q$13(
        .d(bx_q$13$d),
        .q(bx_q$13$q),
        .clock(bx_q$13$clock)
    );
    top$lanes$2$ctl$bx_q$14 bx_q$14(
        .d(bx_q$14$d),
        .q(bx_q$14$q),
        .clock(bx_q$14$clock)
    );
    top$lanes$2$ctl$bx_q$15 bx_q$15(
        .d(bx_q$15$d),
        .q(bx_q$15$q),
        .clock(bx_q$15$clock)
    );
    top$lanes$2$ctl$bx_q$16 bx_q$16(
        .d(bx_q$16$d),
        .q(bx_q$16$q),
        .clock(bx_q$16$clock)
    );
    top$lanes$2$ctl$bx_q$17 bx_q$17(
        .d(bx_q$17$d),
        .q(bx_q$17$q),
        .clock(bx_q$17$clock)
    );
    top$lanes$2$ctl$bx_q$18 bx_q$18(
        .d(bx_q$18$d),
        .q(bx_q$18$q),
        .clock(bx_q$18$clock)
    );
    top$lanes$2$ctl$bx_q$19 bx_q$19(
        .d(bx_q$19$d),
        .q(bx_q$19$q),
        .clock(bx_q$19$clock)
    );
    top$lanes$2$ctl$bx_q$20 bx_q$20(
        .d(bx_q$20$d),
        .q(bx_q$20$q),
        .clock(bx_q$20$clock)
    );
    top$lanes$2$ctl$by_q$0 by_q$0(
        .d(by_q$0$d),
        .q(by_q$0$q),
        .clock(by_q$0$clock)
    );
    top$lanes$2$ctl$by_q$1 by_q$1(
        .d(by_q$1$d),
        .q(by_q$1$q),
        .clock(by_q$1$clock)
    );
    top$lanes$2$ctl$by_q$2 by_q$2(
        .d(by_q$2$d),
        .q(by_q$2$q),
        .clock(by_q$2$clock)
    );
    top$lanes$2$ctl$by_q$3 by_q$3(
        .d(by_q$3$d),
        .q(by_q$3$q),
        .clock(by_q$3$clock)
    );
    top$lanes$2$ctl$by_q$4 by_q$4(
        .d(by_q$4$d),
        .q(by_q$4$q),
        .clock(by_q$4$clock)
    );
    top$lanes$2$ctl$by_q$5 by_q$5(
        .d(by_q$5$d),
        .q(by_q$5$q),
        .clock(by_q$5$clock)
    );
    top$lanes$2$ctl$by_q$6 by_q$6(
        .d(by_q$6$d),
        .q(by_q$6$q),
        .clock(by_q$6$clock)
    );
    top$lanes$2$ctl$by_q$7 by_q$7(
        .d(by_q$7$d),
        .q(by_q$7$q),
        .clock(by_q$7$clock)
    );
    top$lanes$2$ctl$by_q$8 by_q$8(
        .d(by_q$8$d),
        .q(by_q$8$q),
        .clock(by_q$8$clock)
    );
    top$lanes$2$ctl$by_q$9 by_q$9(
        .d(by_q$9$d),
        .q(by_q$9$q),
        .clock(by_q$9$clock)
    );
    top$lanes$2$ctl$by_q$10 by_q$10(
        .d(by_q$10$d),
        .q(by_q$10$q),
        .clock(by_q$10$clock)
    );
    top$lanes$2$ctl$by_q$11 by_q$11(
        .d(by_q$11$d),
        .q(by_q$11$q),
        .clock(by_q$11$clock)
    );
    top$lanes$2$ctl$by_q$12 by_q$12(
        .d(by_q$12$d),
        .q(by_q$12$q),
        .clock(by_q$12$clock)
    );
    top$lanes$2$ctl$by_q$13 by_q$13(
        .d(by_q$13$d),
        .q(by_q$13$q),
        .clock(by_q$13$clock)
    );
    top$lanes$2$ctl$by_q$14 by_q$14(
        .d(by_q$14$d),
        .q(by_q$14$q),
        .clock(by_q$14$clock)
    );
    top$lanes$2$ctl$by_q$15 by_q$15(
        .d(by_q$15$d),
        .q(by_q$15$q),
        .clock(by_q$15$clock)
    );
    top$lanes$2$ctl$by_q$16 by_q$16(
        .d(by_q$16$d),
        .q(by_q$16$q),
        .clock(by_q$16$clock)
    );
    top$lanes$2$ctl$by_q$17 by_q$17(
        .d(by_q$17$d),
        .q(by_q$17$q),
        .clock(by_q$17$clock)
    );
    top$lanes$2$ctl$by_q$18 by_q$18(
        .d(by_q$18$d),
        .q(by_q$18$q),
        .clock(by_q$18$clock)
    );
    top$lanes$2$ctl$by_q$19 by_q$19(
        .d(by_q$19$d),
        .q(by_q$19$q),
        .clock(by_q$19$clock)
    );
    top$lanes$2$ctl$by_q$20 by_q$20(
        .d(by_q$20$d),
        .q(by_q$20$q),
        .clock(by_q$20$clock)
    );
    top$lanes$2$ctl$face_q$0 face_q$0(
        .d(face_q$0$d),
        .q(face_q$0$q),
        .clock(face_q$0$clock)
    );
    top$lanes$2$ctl$face_q$1 face_q$1(
        .d(face_q$1$d),
        .q(face_q$1$q),
        .clock(face_q$1$clock)
    );
    top$lanes$2$ctl$face_q$2 face_q$2(
        .d(face_q$2$d),
        .q(face_q$2$q),
        .clock(face_q$2$clock)
    );
    top$lanes$2$ctl$face_q$3 face_q$3(
        .d(face_q$3$d),
        .q(face_q$3$q),
        .clock(face_q$3$clock)
    );
    top$lanes$2$ctl$face_q$4 face_q$4(
        .d(face_q$4$d),
        .q(face_q$4$q),
        .clock(face_q$4$clock)
    );
    top$lanes$2$ctl$face_q$5 face_q$5(
        .d(face_q$5$d),
        .q(face_q$5$q),
        .clock(face_q$5$clock)
    );
    top$lanes$2$ctl$face_q$6 face_q$6(
        .d(face_q$6$d),
        .q(face_q$6$q),
        .clock(face_q$6$clock)
    );
    top$lanes$2$ctl$face_q$7 face_q$7(
        .d(face_q$7$d),
        .q(face_q$7$q),
        .clock(face_q$7$clock)
    );
    top$lanes$2$ctl$face_q$8 face_q$8(
        .d(face_q$8$d),
        .q(face_q$8$q),
        .clock(face_q$8$clock)
    );
    top$lanes$2$ctl$face_q$9 face_q$9(
        .d(face_q$9$d),
        .q(face_q$9$q),
        .clock(face_q$9$clock)
    );
    top$lanes$2$ctl$face_q$10 face_q$10(
        .d(face_q$10$d),
        .q(face_q$10$q),
        .clock(face_q$10$clock)
    );
    top$lanes$2$ctl$face_q$11 face_q$11(
        .d(face_q$11$d),
        .q(face_q$11$q),
        .clock(face_q$11$clock)
    );
    top$lanes$2$ctl$face_q$12 face_q$12(
        .d(face_q$12$d),
        .q(face_q$12$q),
        .clock(face_q$12$clock)
    );
    top$lanes$2$ctl$face_q$13 face_q$13(
        .d(face_q$13$d),
        .q(face_q$13$q),
        .clock(face_q$13$clock)
    );
    top$lanes$2$ctl$face_q$14 face_q$14(
        .d(face_q$14$d),
        .q(face_q$14$q),
        .clock(face_q$14$clock)
    );
    top$lanes$2$ctl$face_q$15 face_q$15(
        .d(face_q$15$d),
        .q(face_q$15$q),
        .clock(face_q$15$clock)
    );
    top$lanes$2$ctl$face_q$16 face_q$16(
        .d(face_q$16$d),
        .q(face_q$16$q),
        .clock(face_q$16$clock)
    );
    top$lanes$2$ctl$face_q$17 face_q$17(
        .d(face_q$17$d),
        .q(face_q$17$q),
        .clock(face_q$17$clock)
    );
    top$lanes$2$ctl$face_q$18 face_q$18(
        .d(face_q$18$d),
        .q(face_q$18$q),
        .clock(face_q$18$clock)
    );
    top$lanes$2$ctl$face_q$19 face_q$19(
        .d(face_q$19$d),
        .q(face_q$19$q),
        .clock(face_q$19$clock)
    );
    top$lanes$2$ctl$face_q$20 face_q$20(
        .d(face_q$20$d),
        .q(face_q$20$q),
        .clock(face_q$20$clock)
    );
    
    // Update code
    always @(*) begin
        nx_last$clock = clock;
        ny_last$clock = clock;
        nx_last$d = nx_last$q;
        ny_last$d = ny_last$q;
        x_q$0$clock = clock;
        dxm_q$0$clock = clock;
        dym_q$0$clock = clock;
        x_q$1$clock = clock;
        dxm_q$1$clock = clock;
        dym_q$1$clock = clock;
        x_q$2$clock = clock;
        dxm_q$2$clock = clock;
        dym_q$2$clock = clock;
        x_q$3$clock = clock;
        dxm_q$3$clock = clock;
        dym_q$3$clock = clock;
        x_q$4$clock = clock;
        dxm_q$4$clock = clock;
        dym_q$4$clock = clock;
        x_q$5$clock = clock;
        dxm_q$5$clock = clock;
        dym_q$5$clock = clock;
        x_q$6$clock = clock;
        dxm_q$6$clock = clock;
        dym_q$6$clock = clock;
        x_q$7$clock = clock;
        dxm_q$7$clock = clock;
        dym_q$7$clock = clock;
        x_q$8$clock = clock;
        dxm_q$8$clock = clock;
        dym_q$8$clock = clock;
        x_q$9$clock = clock;
        dxm_q$9$clock = clock;
        dym_q$9$clock = clock;
        v_q$0$clock = clock;
        er_q$0$clock = clock;
        pad_q$0$clock = clock;
        bx_q$0$clock = clock;
        by_q$0$clock = clock;
        face_q$0$clock = clock;
        v_q$1$clock = clock;
        er_q$1$clock = clock;
        pad_q$1$clock = clock;
        bx_q$1$clock = clock;
        by_q$1$clock = clock;
        face_q$1$clock = clock;
        v_q$2$clock = clock;
        er_q$2$clock = clock;
        pad_q$2$clock = clock;
        bx_q$2$clock = clock;
        by_q$2$clock = clock;
        face_q$2$clock = clock;
        v_q$3$clock = clock;
        er_q$3$clock = clock;
        pad_q$3$clock = clock;
        bx_q$3$clock = clock;
        by_q$3$clock = clock;
        face_q$3$clock = clock;
        v_q$4$clock = clock;
        er_q$4$clock = clock;
        pad_q$4$clock = clock;
        bx_q$4$clock = clock;
        by_q$4$clock = clock;
        face_q$4$clock = clock;
        v_q$5$clock = clock;
        er_q$5$clock = clock;
        pad_q$5$clock = clock;
        bx_q$5$clock = clock;
        by_q$5$clock = clock;
        face_q$5$clock = clock;
        v_q$6$clock = clock;
        er_q$6$clock = clock;
        pad_q$6$clock = clock;
        bx_q$6$clock = clock;
        by_q$6$clock = clock;
        face_q$6$clock = clock;
        v_q$7$clock = clock;
        er_q$7$clock = clock;
        pad_q$7$clock = clock;
        bx_q$7$clock = clock;
        by_q$7$clock = clock;
        face_q$7$clock = clock;
        v_q$8$clock = clock;
        er_q$8$clock = clock;
        pad_q$8$clock = clock;
        bx_q$8$clock = clock;
        by_q$8$clock = clock;
        face_q$8$clock = clock;
        v_q$9$clock = clock;
        er_q$9$clock = clock;
        pad_q$9$clock = clock;
        bx_q$9$clock = clock;
        by_q$9$clock = clock;
        face_q$9$clock = clock;
        v_q$10$clock = clock;
        er_q$10$clock = clock;
        pad_q$10$clock = clock;
        bx_q$10$clock = clock;
        by_q$10$clock = clock;
        face_q$10$clock = clock;
        v_q$11$clock = clock;
        er_q$11$clock = clock;
        pad_q$11$clock = clock;
        bx_q$11$clock = clock;
        by_q$11$clock = clock;
        face_q$11$clock = clock;
        v_q$12$clock = clock;
        er_q$12$clock = clock;
        pad_q$12$clock = clock;
        bx_q$12$clock = clock;
        by_q$12$clock = clock;
        face_q$12$clock = clock;
        v_q$13$clock = clock;
        er_q$13$clock = clock;
        pad_q$13$clock = clock;
        bx_q$13$clock = clock;
        by_q$13$clock = clock;
        face_q$13$clock = clock;
        v_q$14$clock = clock;
        er_q$14$clock = clock;
        pad_q$14$clock = clock;
        bx_q$14$clock = clock;
        by_q$14$clock = clock;
        face_q$14$clock = clock;
        v_q$15$clock = clock;
        er_q$15$clock = clock;
        pad_q$15$clock = clock;
        bx_q$15$clock = clock;
        by_q$15$clock = clock;
        face_q$15$clock = clock;
        v_q$16$clock = clock;
        er_q$16$clock = clock;
        pad_q$16$clock = clock;
        bx_q$16$clock = clock;
        by_q$16$clock = clock;
        face_q$16$clock = clock;
        v_q$17$clock = clock;
        er_q$17$clock = clock;
        pad_q$17$clock = clock;
        bx_q$17$clock = clock;
        by_q$17$clock = clock;
        face_q$17$clock = clock;
        v_q$18$clock = clock;
        er_q$18$clock = clock;
        pad_q$18$clock = clock;
        bx_q$18$clock = clock;
        by_q$18$clock = clock;
        face_q$18$clock = clock;
        v_q$19$clock = clock;
        er_q$19$clock = clock;
        pad_q$19$clock = clock;
        bx_q$19$clock = clock;
        by_q$19$clock = clock;
        face_q$19$clock = clock;
        v_q$20$clock = clock;
        er_q$20$clock = clock;
        pad_q$20$clock = clock;
        bx_q$20$clock = clock;
        by_q$20$clock = clock;
        face_q$20$clock = clock;
        x_q$0$d = x & coord_mask;
        y_q$0$d = y & coord_mask;
        sr_q$0$d = sr;
        dxn_q$0$d = dx_neg;
        dxm_q$0$d = dx_mag;
        dyn_q$0$d = dy_neg;
        dym_q$0$d = dy_mag;
        x_q$1$d = x_q$0$q;
        dxm_q$1$d = dxm_q$0$q;
        dym_q$1$d = dym_q$0$q;
        x_q$2$d = x_q$1$q;
        dxm_q$2$d = dxm_q$1$q;
        dym_q$2$d = dym_q$1$q;
        x_q$3$d = x_q$2$q;
        dxm_q$3$d = dxm_q$2$q;
        dym_q$3$d = dym_q$2$q;
        x_q$4$d = x_q$3$q;
        dxm_q$4$d = dxm_q$3$q;
        dym_q$4$d = dym_q$3$q;
        x_q$5$d = x_q$4$q;
        dxm_q$5$d = dxm_q$4$q;
        dym_q$5$d = dym_q$4$q;
        x_q$6$d = x_q$5$q;
        dxm_q$6$d = dxm_q$5$q;
        dym_q$6$d = dym_q$5$q;
        x_q$7$d = x_q$6$q;
        dxm_q$7$d = dxm_q$6$q;
        dym_q$7$d = dym_q$6$q;
        x_q$8$d = x_q$7$q;
        dxm_q$8$d = dxm_q$7$q;
        dym_q$8$d = dym_q$7$q;
        x_q$9$d = x_q$8$q;
        dxm_q$9$d = dxm_q$8$q;
        dym_q$9$d = dym_q$8$q;
        y_q$0$clock = clock;
        sr_q$0$clock = clock;
        dxn_q$0$clock = clock;
        dyn_q$0$clock = clock;
        y_q$1$clock = clock;
        sr_q$1$clock = clock;
        dxn_q$1$clock = clock;
        dyn_q$1$clock = clock;
        y_q$2$clock = clock;
        sr_q$2$clock = clock;
        dxn_q$2$clock = clock;
        dyn_q$2$clock = clock;
        y_q$3$clock = clock;
        sr_q$3$clock = clock;
        dxn_q$3$clock = clock;
        dyn_q$3$clock = clock;
        y_q$4$clock = clock;
        sr_q$4$clock = clock;
        dxn_q$4$clock = clock;
        dyn_q$4$clock = clock;
        y_q$5$clock = clock;
        sr_q$5$clock = clock;
        dxn_q$5$clock = clock;
        dyn_q$5$clock = clock;
        y_q$6$clock = clock;
        sr_q$6$clock = clock;
        dxn_q$6$clock = clock;
        dyn_q$6$clock = clock;
        y_q$7$clock = clock;
        sr_q$7$clock = clock;
        dxn_q$7$clock = clock;
        dyn_q$7$clock = clock;
        y_q$8$clock = clock;
        sr_q$8$clock = clock;
        dxn_q$8$clock = clock;
        dyn_q$8$clock = clock;
        y_q$1$d = y_q$0$q;
        sr_q$1$d = sr_q$0$q;
        dxn_q$1$d = dxn_q$0$q;
        dyn_q$1$d = dyn_q$0$q;
        y_q$2$d = y_q$1$q;
        sr_q$2$d = sr_q$1$q;
        dxn_q$2$d = dxn_q$1$q;
        dyn_q$2$d = dyn_q$1$q;
        y_q$3$d = y_q$2$q;
        sr_q$3$d = sr_q$2$q;
        dxn_q$3$d = dxn_q$2$q;
        dyn_q$3$d = dyn_q$2$q;
        y_q$4$d = y_q$3$q;
        sr_q$4$d = sr_q$3$q;
        dxn_q$4$d = dxn_q$3$q;
        dyn_q$4$d = dyn_q$3$q;
        y_q$5$d = y_q$4$q;
        sr_q$5$d = sr_q$4$q;
        dxn_q$5$d = dxn_q$4$q;
        dyn_q$5$d = dyn_q$4$q;
        y_q$6$d = y_q$5$q;
        sr_q$6$d = sr_q$5$q;
        dxn_q$6$d = dxn_q$5$q;
        dyn_q$6$d = dyn_q$5$q;
        y_q$7$d = y_q$6$q;
        sr_q$7$d = sr_q$6$q;
        dxn_q$7$d = dxn_q$6$q;
        dyn_q$7$d = dyn_q$6$q;
        y_q$8$d = y_q$7$q;
        sr_q$8$d = sr_q$7$q;
        dxn_q$8$d = dxn_q$7$q;
        dyn_q$8$d = dyn_q$7$q;
        x_t = x_q$9$q;
        dx_mag_t = dxm_q$9$q;
        dy_mag_t = dym_q$9$q;
        nx_last$d = dims[('h0)+:(16)] - 'h1;
        ny_last$d = dims[('h10)+:(16)] - 'h1;
        x_out = 1'b0;
        if (dxm_q$8$q != 'h0) begin
            if (dxn_q$8$q) begin
                x_out = x_q$8$q == nx_last$q;
            end
            else begin
                x_out = x_q$8$q == 'h0;
            end
        end
        y_out = 1'b0;
        if (dym_q$8$q != 'h0) begin
            if (dyn_q$8$q) begin
                y_out = y_q$8$q == ny_last$q;
            end
            else begin
                y_out = y_q$8$q == 'h0;
            end
        end
        dx_nz = dxm_q$8$q != 'h0;
        dy_nz = dym_q$8$q != 'h0;
        sel = 7'(sr_q$8$q) | (7'(dxn_q$8$q) << 'h1) | (7'(dx_nz) << 'h2) | (7'(dyn_q$8$q) << 'h3) | (7'(dy_nz) << 'h4) | (7'(x_out) << 'h5) | (7'(y_out) << 'h6);
        sel_q$0$clock = clock;
        sel_q$0$d = sel;
        sel_t$0 = sel_q$0$q;
        sel_q$1$clock = clock;
        sel_q$1$d = sel;
        sel_t$1 = sel_q$1$q;
        sel_q$2$clock = clock;
        sel_q$2$d = sel;
        sel_t$2 = sel_q$2$q;
        sel_q$3$clock = clock;
        sel_q$3$d = sel;
        sel_t$3 = sel_q$3$q;
        v_q$0$d = valid;
        er_q$0$d = er;
        pad_q$0$d = pad;
        bx_q$0$d = base_x & coord_mask;
        by_q$0$d = base_y & coord_mask;
        face_q$0$d = face;
        v_q$1$d = v_q$0$q;
        er_q$1$d = er_q$0$q;
        pad_q$1$d = pad_q$0$q;
        bx_q$1$d = bx_q$0$q;
        by_q$1$d = by_q$0$q;
        face_q$1$d = face_q$0$q;
        v_q$2$d = v_q$1$q;
        er_q$2$d = er_q$1$q;
        pad_q$2$d = pad_q$1$q;
        bx_q$2$d = bx_q$1$q;
        by_q$2$d = by_q$1$q;
        face_q$2$d = face_q$1$q;
        v_q$3$d = v_q$2$q;
        er_q$3$d = er_q$2$q;
        pad_q$3$d = pad_q$2$q;
        bx_q$3$d = bx_q$2$q;
        by_q$3$d = by_q$2$q;
        face_q$3$d = face_q$2$q;
        v_q$4$d = v_q$3$q;
        er_q$4$d = er_q$3$q;
        pad_q$4$d = pad_q$3$q;
        bx_q$4$d = bx_q$3$q;
        by_q$4$d = by_q$3$q;
        face_q$4$d = face_q$3$q;
        v_q$5$d = v_q$4$q;
        er_q$5$d = er_q$4$q;
        pad_q$5$d = pad_q$4$q;
        bx_q$5$d = bx_q$4$q;
        by_q$5$d = by_q$4$q;
        face_q$5$d = face_q$4$q;
        v_q$6$d = v_q$5$q;
        er_q$6$d = er_q$5$q;
        pad_q$6$d = pad_q$5$q;
        bx_q$6$d = bx_q$5$q;
        by_q$6$d = by_q$5$q;
        face_q$6$d = face_q$5$q;
        v_q$7$d = v_q$6$q;
        er_q$7$d = er_q$6$q;
        pad_q$7$d = pad_q$6$q;
        bx_q$7$d = bx_q$6$q;
        by_q$7$d = by_q$6$q;
        face_q$7$d = face_q$6$q;
        v_q$8$d = v_q$7$q;
        er_q$8$d = er_q$7$q;
        pad_q$8$d = pad_q$7$q;
        bx_q$8$d = bx_q$7$q;
        by_q$8$d = by_q$7$q;
        face_q$8$d = face_q$7$q;
        v_q$9$d = v_q$8$q;
        er_q$9$d = er_q$8$q;
        pad_q$9$d = pad_q$8$q;
        bx_q$9$d = bx_q$8$q;
        by_q$9$d = by_q$8$q;
        face_q$9$d = face_q$8$q;
        v_q$10$d = v_q$9$q;
        er_q$10$d = er_q$9$q;
        pad_q$10$d = pad_q$9$q;
        bx_q$10$d = bx_q$9$q;
        by_q$10$d = by_q$9$q;
        face_q$10$d = face_q$9$q;
        v_q$11$d = v_q$10$q;
        er_q$11$d = er_q$10$q;
        pad_q$11$d = pad_q$10$q;
        bx_q$11$d = bx_q$10$q;
        by_q$11$d = by_q$10$q;
        face_q$11$d = face_q$10$q;
        v_q$12$d = v_q$11$q;
        er_q$12$d = er_q$11$q;
        pad_q$12$d = pad_q$11$q;
        bx_q$12$d = bx_q$11$q;
        by_q$12$d = by_q$11$q;
        face_q$12$d = face_q$11$q;
        v_q$13$d = v_q$12$q;
        er_q$13$d = er_q$12$q;
        pad_q$13$d = pad_q$12$q;
        bx_q$13$d = bx_q$12$q;
        by_q$13$d = by_q$12$q;
        face_q$13$d = face_q$12$q;
        v_q$14$d = v_q$13$q;
        er_q$14$d = er_q$13$q;
        pad_q$14$d = pad_q$13$q;
        bx_q$14$d = bx_q$13$q;
        by_q$14$d = by_q$13$q;
        face_q$14$d = face_q$13$q;
        v_q$15$d = v_q$14$q;
        er_q$15$d = er_q$14$q;
        pad_q$15$d = pad_q$14$q;
        bx_q$15$d = bx_q$14$q;
        by_q$15$d = by_q$14$q;
        face_q$15$d = face_q$14$q;
        v_q$16$d = v_q$15$q;
        er_q$16$d = er_q$15$q;
        pad_q$16$d = pad_q$15$q;
        bx_q$16$d = bx_q$15$q;
        by_q$16$d = by_q$15$q;
        face_q$16$d = face_q$15$q;
        v_q$17$d = v_q$16$q;
        er_q$17$d = er_q$16$q;
        pad_q$17$d = pad_q$16$q;
        bx_q$17$d = bx_q$16$q;
        by_q$17$d = by_q$16$q;
        face_q$17$d = face_q$16$q;
        v_q$18$d = v_q$17$q;
        er_q$18$d = er_q$17$q;
        pad_q$18$d = pad_q$17$q;
        bx_q$18$d = bx_q$17$q;
        by_q$18$d = by_q$17$q;
        face_q$18$d = face_q$17$q;
        v_q$19$d = v_q$18$q;
        er_q$19$d = er_q$18$q;
        pad_q$19$d = pad_q$18$q;
        bx_q$19$d = bx_q$18$q;
        by_q$19$d = by_q$18$q;
        face_q$19$d = face_q$18$q;
        v_q$20$d = v_q$19$q;
        er_q$20$d = er_q$19$q;
        pad_q$20$d = pad_q$19$q;
        bx_q$20$d = bx_q$19$q;
        by_q$20$d = by_q$19$q;
        face_q$20$d = face_q$19$q;
        res_beat = v_q$20$q;
        res_valid = v_q$20$q & ~pad_q$20$q;
        px_valid = v_q$20$q & er_q$20$q & ~pad_q$20$q;
        px_x = bx_q$20$q;
        px_y = by_q$20$q;
        px_face = face_q$20$q;
    end
    
endmodule // top$lanes$2$ctl
module top$lanes$2$ctl$bx_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$0
module top$lanes$2$ctl$bx_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$1
module top$lanes$2$ctl$bx_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$10
module top$lanes$2$ctl$bx_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$11
module top$lanes$2$ctl$bx_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$12
module top$lanes$2$ctl$bx_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$13
module top$lanes$2$ctl$bx_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$14
module top$lanes$2$ctl$bx_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$15
module top$lanes$2$ctl$bx_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$16
module top$lanes$2$ctl$bx_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$17
module top$lanes$2$ctl$bx_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$18
module top$lanes$2$ctl$bx_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$19
module top$lanes$2$ctl$bx_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$2
module top$lanes$2$ctl$bx_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$20
module top$lanes$2$ctl$bx_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$3
module top$lanes$2$ctl$bx_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$4
module top$lanes$2$ctl$bx_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$5
module top$lanes$2$ctl$bx_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$6
module top$lanes$2$ctl$bx_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$7
module top$lanes$2$ctl$bx_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$8
module top$lanes$2$ctl$bx_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$bx_q$9
module top$lanes$2$ctl$by_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$0
module top$lanes$2$ctl$by_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$1
module top$lanes$2$ctl$by_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$10
module top$lanes$2$ctl$by_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$11
module top$lanes$2$ctl$by_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$12
module top$lanes$2$ctl$by_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$13
module top$lanes$2$ctl$by_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$14
module top$lanes$2$ctl$by_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$15
module top$lanes$2$ctl$by_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$16
module top$lanes$2$ctl$by_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$17
module top$lanes$2$ctl$by_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$18
module top$lanes$2$ctl$by_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$19
module top$lanes$2$ctl$by_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$2
module top$lanes$2$ctl$by_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$20
module top$lanes$2$ctl$by_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$3
module top$lanes$2$ctl$by_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$4
module top$lanes$2$ctl$by_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$5
module top$lanes$2$ctl$by_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$6
module top$lanes$2$ctl$by_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$7
module top$lanes$2$ctl$by_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$8
module top$lanes$2$ctl$by_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$by_q$9
module top$lanes$2$ctl$dxm_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxm_q$0
module top$lanes$2$ctl$dxm_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxm_q$1
module top$lanes$2$ctl$dxm_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxm_q$2
module top$lanes$2$ctl$dxm_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxm_q$3
module top$lanes$2$ctl$dxm_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxm_q$4
module top$lanes$2$ctl$dxm_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxm_q$5
module top$lanes$2$ctl$dxm_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxm_q$6
module top$lanes$2$ctl$dxm_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxm_q$7
module top$lanes$2$ctl$dxm_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxm_q$8
module top$lanes$2$ctl$dxm_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxm_q$9
module top$lanes$2$ctl$dxn_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxn_q$0
module top$lanes$2$ctl$dxn_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxn_q$1
module top$lanes$2$ctl$dxn_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxn_q$2
module top$lanes$2$ctl$dxn_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxn_q$3
module top$lanes$2$ctl$dxn_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxn_q$4
module top$lanes$2$ctl$dxn_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxn_q$5
module top$lanes$2$ctl$dxn_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxn_q$6
module top$lanes$2$ctl$dxn_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxn_q$7
module top$lanes$2$ctl$dxn_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dxn_q$8
module top$lanes$2$ctl$dym_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dym_q$0
module top$lanes$2$ctl$dym_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dym_q$1
module top$lanes$2$ctl$dym_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dym_q$2
module top$lanes$2$ctl$dym_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dym_q$3
module top$lanes$2$ctl$dym_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dym_q$4
module top$lanes$2$ctl$dym_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dym_q$5
module top$lanes$2$ctl$dym_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dym_q$6
module top$lanes$2$ctl$dym_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dym_q$7
module top$lanes$2$ctl$dym_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dym_q$8
module top$lanes$2$ctl$dym_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dym_q$9
module top$lanes$2$ctl$dyn_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dyn_q$0
module top$lanes$2$ctl$dyn_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dyn_q$1
module top$lanes$2$ctl$dyn_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dyn_q$2
module top$lanes$2$ctl$dyn_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dyn_q$3
module top$lanes$2$ctl$dyn_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dyn_q$4
module top$lanes$2$ctl$dyn_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dyn_q$5
module top$lanes$2$ctl$dyn_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dyn_q$6
module top$lanes$2$ctl$dyn_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dyn_q$7
module top$lanes$2$ctl$dyn_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$dyn_q$8
module top$lanes$2$ctl$er_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$0
module top$lanes$2$ctl$er_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$1
module top$lanes$2$ctl$er_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$10
module top$lanes$2$ctl$er_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$11
module top$lanes$2$ctl$er_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$12
module top$lanes$2$ctl$er_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$13
module top$lanes$2$ctl$er_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$14
module top$lanes$2$ctl$er_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$15
module top$lanes$2$ctl$er_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$16
module top$lanes$2$ctl$er_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$17
module top$lanes$2$ctl$er_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$18
module top$lanes$2$ctl$er_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$19
module top$lanes$2$ctl$er_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$2
module top$lanes$2$ctl$er_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$20
module top$lanes$2$ctl$er_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$3
module top$lanes$2$ctl$er_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$4
module top$lanes$2$ctl$er_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$5
module top$lanes$2$ctl$er_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$6
module top$lanes$2$ctl$er_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$7
module top$lanes$2$ctl$er_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$8
module top$lanes$2$ctl$er_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$er_q$9
module top$lanes$2$ctl$face_q$0(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$0
module top$lanes$2$ctl$face_q$1(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$1
module top$lanes$2$ctl$face_q$10(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$10
module top$lanes$2$ctl$face_q$11(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$11
module top$lanes$2$ctl$face_q$12(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$12
module top$lanes$2$ctl$face_q$13(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$13
module top$lanes$2$ctl$face_q$14(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$14
module top$lanes$2$ctl$face_q$15(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$15
module top$lanes$2$ctl$face_q$16(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$16
module top$lanes$2$ctl$face_q$17(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$17
module top$lanes$2$ctl$face_q$18(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$18
module top$lanes$2$ctl$face_q$19(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$19
module top$lanes$2$ctl$face_q$2(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$2
module top$lanes$2$ctl$face_q$20(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$20
module top$lanes$2$ctl$face_q$3(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$3
module top$lanes$2$ctl$face_q$4(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$4
module top$lanes$2$ctl$face_q$5(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$5
module top$lanes$2$ctl$face_q$6(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$6
module top$lanes$2$ctl$face_q$7(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$7
module top$lanes$2$ctl$face_q$8(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$8
module top$lanes$2$ctl$face_q$9(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$ctl$face_q$9
module top$lanes$2$ctl$nx_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$ctl$nx_last
module top$lanes$2$ctl$ny_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$ctl$ny_last
module top$lanes$2$ctl$pad_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$0
module top$lanes$2$ctl$pad_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$1
module top$lanes$2$ctl$pad_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$10
module top$lanes$2$ctl$pad_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$11
module top$lanes$2$ctl$pad_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$12
module top$lanes$2$ctl$pad_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$13
module top$lanes$2$ctl$pad_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$14
module top$lanes$2$ctl$pad_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$15
module top$lanes$2$ctl$pad_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$16
module top$lanes$2$ctl$pad_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$17
module top$lanes$2$ctl$pad_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$18
module top$lanes$2$ctl$pad_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$19
module top$lanes$2$ctl$pad_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$2
module top$lanes$2$ctl$pad_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$20
module top$lanes$2$ctl$pad_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$3
module top$lanes$2$ctl$pad_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$4
module top$lanes$2$ctl$pad_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$5
module top$lanes$2$ctl$pad_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$6
module top$lanes$2$ctl$pad_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$7
module top$lanes$2$ctl$pad_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$8
module top$lanes$2$ctl$pad_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$pad_q$9
module top$lanes$2$ctl$sel_q$0(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$ctl$sel_q$0
module top$lanes$2$ctl$sel_q$1(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$ctl$sel_q$1
module top$lanes$2$ctl$sel_q$2(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$ctl$sel_q$2
module top$lanes$2$ctl$sel_q$3(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$2$ctl$sel_q$3
module top$lanes$2$ctl$sr_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$sr_q$0
module top$lanes$2$ctl$sr_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$sr_q$1
module top$lanes$2$ctl$sr_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$sr_q$2
module top$lanes$2$ctl$sr_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$sr_q$3
module top$lanes$2$ctl$sr_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$sr_q$4
module top$lanes$2$ctl$sr_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$sr_q$5
module top$lanes$2$ctl$sr_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$sr_q$6
module top$lanes$2$ctl$sr_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$sr_q$7
module top$lanes$2$ctl$sr_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$sr_q$8
module top$lanes$2$ctl$v_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$0
module top$lanes$2$ctl$v_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$1
module top$lanes$2$ctl$v_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$10
module top$lanes$2$ctl$v_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$11
module top$lanes$2$ctl$v_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$12
module top$lanes$2$ctl$v_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$13
module top$lanes$2$ctl$v_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$14
module top$lanes$2$ctl$v_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$15
module top$lanes$2$ctl$v_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$16
module top$lanes$2$ctl$v_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$17
module top$lanes$2$ctl$v_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$18
module top$lanes$2$ctl$v_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$19
module top$lanes$2$ctl$v_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$2
module top$lanes$2$ctl$v_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$20
module top$lanes$2$ctl$v_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$3
module top$lanes$2$ctl$v_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$4
module top$lanes$2$ctl$v_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$5
module top$lanes$2$ctl$v_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$6
module top$lanes$2$ctl$v_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$7
module top$lanes$2$ctl$v_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$8
module top$lanes$2$ctl$v_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$v_q$9
module top$lanes$2$ctl$x_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$x_q$0
module top$lanes$2$ctl$x_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$x_q$1
module top$lanes$2$ctl$x_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$x_q$2
module top$lanes$2$ctl$x_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$x_q$3
module top$lanes$2$ctl$x_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$x_q$4
module top$lanes$2$ctl$x_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$x_q$5
module top$lanes$2$ctl$x_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$x_q$6
module top$lanes$2$ctl$x_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$x_q$7
module top$lanes$2$ctl$x_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$x_q$8
module top$lanes$2$ctl$x_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$x_q$9
module top$lanes$2$ctl$y_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$y_q$0
module top$lanes$2$ctl$y_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$y_q$1
module top$lanes$2$ctl$y_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$y_q$2
module top$lanes$2$ctl$y_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$y_q$3
module top$lanes$2$ctl$y_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$y_q$4
module top$lanes$2$ctl$y_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$y_q$5
module top$lanes$2$ctl$y_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$y_q$6
module top$lanes$2$ctl$y_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$y_q$7
module top$lanes$2$ctl$y_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$2$ctl$y_q$8
module top$lanes$2$feed(clock,beats,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,o_valid,o_value,o_x,o_y,o_pad,o_invalid,o_sr,o_er,o_edge,o_face,o_base_x,o_base_y,o_dx_neg,o_dx_mag,o_dy_neg,o_dy_mag,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  o_valid;
    output reg  [15:0] o_value;
    output reg  [15:0] o_x;
    output reg  [15:0] o_y;
    output reg  o_pad;
    output reg  o_invalid;
    output reg  o_sr;
    output reg  o_er;
    output reg  o_edge;
    output reg  [2:0] o_face;
    output reg  [15:0] o_base_x;
    output reg  [15:0] o_base_y;
    output reg  o_dx_neg;
    output reg  [15:0] o_dx_mag;
    output reg  o_dy_neg;
    output reg  [15:0] o_dy_mag;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  use_gradient = 1'b0;
    
    // Stub signals
    reg  abc$clock;
    reg  [63:0] abc$beats;
    reg  [15:0] abc$value;
    reg  [15:0] abc$x;
    reg  [15:0] abc$from_left_xm;
    reg  [15:0] abc$from_left_ym;
    reg  [15:0] abc$from_left_zm;
    reg  [15:0] abc$from_right_xp;
    reg  [15:0] abc$from_right_yp;
    reg  [15:0] abc$from_right_zp;
    wire  [15:0] abc$to_right_xm = 'h0;
    wire  [15:0] abc$to_right_ym = 'h0;
    wire  [15:0] abc$to_right_zm = 'h0;
    wire  [15:0] abc$to_left_xp = 'h0;
    wire  [15:0] abc$to_left_yp = 'h0;
    wire  [15:0] abc$to_left_zp = 'h0;
    wire  [15:0] abc$o_value = 'h0;
    wire  abc$gx_neg = 'h0;
    wire  [15:0] abc$gx_mag = 'h0;
    wire  abc$gy_neg = 'h0;
    wire  [15:0] abc$gy_mag = 'h0;
    wire  abc$gz_neg = 'h0;
    wire  [15:0] abc$gz_mag = 'h0;
    
    // Sub module instances
    
    // Update code
    reg  [15:0] o_value_pass;
    always @(*) begin
        abc$clock = clock;
        abc$beats = beats;
        abc$value = value;
        abc$x = x;
        abc$from_left_xm = g_from_left_xm;
        abc$from_left_ym = g_from_left_ym;
        abc$from_left_zm = g_from_left_zm;
        abc$from_right_xp = g_from_right_xp;
        abc$from_right_yp = g_from_right_yp;
        abc$from_right_zp = g_from_right_zp;
        g_to_right_xm = abc$to_right_xm;
        g_to_right_ym = abc$to_right_ym;
        g_to_right_zm = abc$to_right_zm;
        g_to_left_xp = abc$to_left_xp;
        g_to_left_yp = abc$to_left_yp;
        g_to_left_zp = abc$to_left_zp;
        gx_neg = abc$gx_neg;
        gx_mag = abc$gx_mag;
        gy_neg = abc$gy_neg;
        gy_mag = abc$gy_mag;
        gz_neg = abc$gz_neg;
        gz_mag = abc$gz_mag;
        if (use_gradient) begin
            o_value_pass = abc$o_value;
        end
        else begin
            o_value_pass = value;
        end
        o_valid = beat_valid & ~halo;
        o_x = x;
        o_y = y;
        o_pad = pad;
        o_invalid = invalid;
        o_sr = sr;
        o_er = er;
        o_edge = at_edge;
        o_face = face;
        o_base_x = base_x;
        o_base_y = base_y;
        o_dx_neg = dx_neg;
        o_dx_mag = dx_mag;
        o_dy_neg = dy_neg;
        o_dy_mag = dy_mag;
        o_value = o_value_pass;
    end
    
endmodule // top$lanes$2$feed
module top$lanes$3(clock,host_write,host_address,host_data,dims,beats,order,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,res_beat,res_valid,res,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    input wire  [63:0] dims;
    input wire  [63:0] beats;
    input wire  [63:0] order;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  [63:0] t0s0;
    input wire  [63:0] t0i1;
    output reg  [63:0] t1s0;
    output reg  [63:0] t1s1;
    input wire  [63:0] t1i1;
    input wire  [63:0] t1i2;
    output reg  [63:0] t3s0;
    output reg  [63:0] t3s1;
    input wire  [63:0] t3i1;
    input wire  [63:0] t3i2;
    output reg  [63:0] t5s0;
    output reg  [63:0] t5s1;
    output reg  [63:0] t5s2;
    input wire  [63:0] t5i1;
    input wire  [63:0] t5i2;
    input wire  [63:0] t5i3;
    output reg  [63:0] t6s0;
    input wire  [63:0] t6i1;
    output reg  [63:0] t7s0;
    input wire  [63:0] t7i1;
    output reg  [63:0] t8s0;
    input wire  [63:0] t8i1;
    input wire  [63:0] t8il;
    output reg  res_beat;
    output reg  res_valid;
    output reg  [63:0] res;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Constant declarations
    localparam  coord_mask = 16'hff;
    
    // Stub signals
    reg  feed$clock;
    reg  [63:0] feed$beats;
    reg  feed$beat_valid;
    reg  [15:0] feed$value;
    reg  [15:0] feed$x;
    reg  [15:0] feed$y;
    reg  feed$pad;
    reg  feed$invalid;
    reg  feed$halo;
    reg  feed$sr;
    reg  feed$er;
    reg  [15:0] feed$base_x;
    reg  [15:0] feed$base_y;
    reg  [2:0] feed$face;
    reg  feed$at_edge;
    reg  feed$dx_neg;
    reg  [15:0] feed$dx_mag;
    reg  feed$dy_neg;
    reg  [15:0] feed$dy_mag;
    reg  [15:0] feed$g_from_left_xm;
    reg  [15:0] feed$g_from_left_ym;
    reg  [15:0] feed$g_from_left_zm;
    reg  [15:0] feed$g_from_right_xp;
    reg  [15:0] feed$g_from_right_yp;
    reg  [15:0] feed$g_from_right_zp;
    wire  [15:0] feed$g_to_right_xm;
    wire  [15:0] feed$g_to_right_ym;
    wire  [15:0] feed$g_to_right_zm;
    wire  [15:0] feed$g_to_left_xp;
    wire  [15:0] feed$g_to_left_yp;
    wire  [15:0] feed$g_to_left_zp;
    wire  feed$o_valid;
    wire  [15:0] feed$o_value;
    wire  [15:0] feed$o_x;
    wire  [15:0] feed$o_y;
    wire  feed$o_pad;
    wire  feed$o_invalid;
    wire  feed$o_sr;
    wire  feed$o_er;
    wire  feed$o_edge;
    wire  [2:0] feed$o_face;
    wire  [15:0] feed$o_base_x;
    wire  [15:0] feed$o_base_y;
    wire  feed$o_dx_neg;
    wire  [15:0] feed$o_dx_mag;
    wire  feed$o_dy_neg;
    wire  [15:0] feed$o_dy_mag;
    wire  feed$gx_neg;
    wire  [15:0] feed$gx_mag;
    wire  feed$gy_neg;
    wire  [15:0] feed$gy_mag;
    wire  feed$gz_neg;
    wire  [15:0] feed$gz_mag;
    reg  shader$clock;
    reg  shader$host_write;
    reg  [23:0] shader$host_address;
    reg  [63:0] shader$host_data;
    reg  [15:0] shader$value;
    reg  shader$invalid;
    reg  shader$at_edge;
    reg  shader$gx_neg;
    reg  [31:0] shader$gx_mag;
    reg  shader$gy_neg;
    reg  [31:0] shader$gy_mag;
    reg  shader$gz_neg;
    reg  [31:0] shader$gz_mag;
    wire  [31:0] shader$r;
    wire  [15:0] shader$g;
    wire  [15:0] shader$b;
    wire  [15:0] shader$a;
    wire  shader$valid;
    reg  ctl$clock;
    reg  ctl$valid;
    reg  ctl$er;
    reg  ctl$pad;
    reg  [15:0] ctl$base_x;
    reg  [15:0] ctl$base_y;
    reg  [2:0] ctl$face;
    reg  [15:0] ctl$x;
    reg  [15:0] ctl$y;
    reg  ctl$sr;
    reg  ctl$dx_neg;
    reg  [15:0] ctl$dx_mag;
    reg  ctl$dy_neg;
    reg  [15:0] ctl$dy_mag;
    reg  [63:0] ctl$dims;
    reg  [15:0] ctl$coord_mask;
    wire  [15:0] ctl$x_t;
    wire  [15:0] ctl$dx_mag_t;
    wire  [15:0] ctl$dy_mag_t;
    wire  [6:0] ctl$sel_t$0;
    wire  [6:0] ctl$sel_t$1;
    wire  [6:0] ctl$sel_t$2;
    wire  [6:0] ctl$sel_t$3;
    wire  ctl$res_beat;
    wire  ctl$res_valid;
    wire  ctl$px_valid;
    wire  [15:0] ctl$px_x;
    wire  [15:0] ctl$px_y;
    wire  [2:0] ctl$px_face;
    reg  taps$clock;
    reg  [63:0] taps$beats;
    reg  [15:0] taps$x;
    reg  [63:0] taps$res;
    reg  taps$res_beat;
    wire  [63:0] taps$t0s0;
    reg  [63:0] taps$t0i1;
    wire  [63:0] taps$t1s0;
    wire  [63:0] taps$t1s1;
    reg  [63:0] taps$t1i1;
    reg  [63:0] taps$t1i2;
    wire  [63:0] taps$t3s0;
    wire  [63:0] taps$t3s1;
    reg  [63:0] taps$t3i1;
    reg  [63:0] taps$t3i2;
    wire  [63:0] taps$t5s0;
    wire  [63:0] taps$t5s1;
    wire  [63:0] taps$t5s2;
    reg  [63:0] taps$t5i1;
    reg  [63:0] taps$t5i2;
    reg  [63:0] taps$t5i3;
    wire  [63:0] taps$t6s0;
    reg  [63:0] taps$t6i1;
    wire  [63:0] taps$t7s0;
    reg  [63:0] taps$t7i1;
    wire  [63:0] taps$t8s0;
    reg  [63:0] taps$t8i1;
    reg  [63:0] taps$t8il;
    wire  [63:0] taps$a$0;
    wire  [63:0] taps$a$1;
    wire  [63:0] taps$a$2;
    wire  [63:0] taps$a$3;
    wire  [63:0] taps$a$4;
    wire  [63:0] taps$a$5;
    wire  [63:0] taps$a$6;
    wire  [63:0] taps$a$7;
    wire  [63:0] taps$a$8;
    reg  [63:0] cells$a$0;
    reg  [63:0] cells$a$1;
    reg  [63:0] cells$a$2;
    reg  [63:0] cells$a$3;
    reg  [63:0] cells$a$4;
    reg  [63:0] cells$a$5;
    reg  [63:0] cells$a$6;
    reg  [63:0] cells$a$7;
    reg  [63:0] cells$a$8;
    reg  [6:0] cells$sel$0;
    reg  [6:0] cells$sel$1;
    reg  [6:0] cells$sel$2;
    reg  [6:0] cells$sel$3;
    wire  [31:0] cells$c00$0;
    wire  [31:0] cells$c00$1;
    wire  [31:0] cells$c00$2;
    wire  [31:0] cells$c00$3;
    wire  [31:0] cells$c10$0;
    wire  [31:0] cells$c10$1;
    wire  [31:0] cells$c10$2;
    wire  [31:0] cells$c10$3;
    wire  [31:0] cells$c01$0;
    wire  [31:0] cells$c01$1;
    wire  [31:0] cells$c01$2;
    wire  [31:0] cells$c01$3;
    wire  [31:0] cells$c11$0;
    wire  [31:0] cells$c11$1;
    wire  [31:0] cells$c11$2;
    wire  [31:0] cells$c11$3;
    reg  [63:0] cells$order;
    reg  bilinear$clock;
    reg  [31:0] bilinear$c00$0;
    reg  [31:0] bilinear$c00$1;
    reg  [31:0] bilinear$c00$2;
    reg  [31:0] bilinear$c00$3;
    reg  [31:0] bilinear$c10$0;
    reg  [31:0] bilinear$c10$1;
    reg  [31:0] bilinear$c10$2;
    reg  [31:0] bilinear$c10$3;
    reg  [31:0] bilinear$c01$0;
    reg  [31:0] bilinear$c01$1;
    reg  [31:0] bilinear$c01$2;
    reg  [31:0] bilinear$c01$3;
    reg  [31:0] bilinear$c11$0;
    reg  [31:0] bilinear$c11$1;
    reg  [31:0] bilinear$c11$2;
    reg  [31:0] bilinear$c11$3;
    reg  [15:0] bilinear$wx;
    reg  [15:0] bilinear$wy;
    wire  [31:0] bilinear$out$0;
    wire  [31:0] bilinear$out$1;
    wire  [31:0] bilinear$out$2;
    wire  [31:0] bilinear$out$3;
    reg  compositor$clock;
    reg  [31:0] compositor$acc_r;
    reg  [15:0] compositor$acc_g;
    reg  [15:0] compositor$acc_b;
    reg  [15:0] compositor$acc_a;
    reg  [31:0] compositor$new_r;
    reg  [15:0] compositor$new_g;
    reg  [15:0] compositor$new_b;
    reg  [15:0] compositor$new_a;
    reg  compositor$new_valid;
    wire  [31:0] compositor$out_r;
    wire  [15:0] compositor$out_g;
    wire  [15:0] compositor$out_b;
    wire  [15:0] compositor$out_a;
    reg  [63:0] compositor$order;
    
    // Sub module instances
    top$lanes$3$feed feed(
        .clock(feed$clock),
        .beats(feed$beats),
        .beat_valid(feed$beat_valid),
        .value(feed$value),
        .x(feed$x),
        .y(feed$y),
        .pad(feed$pad),
        .invalid(feed$invalid),
        .halo(feed$halo),
        .sr(feed$sr),
        .er(feed$er),
        .base_x(feed$base_x),
        .base_y(feed$base_y),
        .face(feed$face),
        .at_edge(feed$at_edge),
        .dx_neg(feed$dx_neg),
        .dx_mag(feed$dx_mag),
        .dy_neg(feed$dy_neg),
        .dy_mag(feed$dy_mag),
        .g_from_left_xm(feed$g_from_left_xm),
        .g_from_left_ym(feed$g_from_left_ym),
        .g_from_left_zm(feed$g_from_left_zm),
        .g_from_right_xp(feed$g_from_right_xp),
        .g_from_right_yp(feed$g_from_right_yp),
        .g_from_right_zp(feed$g_from_right_zp),
        .g_to_right_xm(feed$g_to_right_xm),
        .g_to_right_ym(feed$g_to_right_ym),
        .g_to_right_zm(feed$g_to_right_zm),
        .g_to_left_xp(feed$g_to_left_xp),
        .g_to_left_yp(feed$g_to_left_yp),
        .g_to_left_zp(feed$g_to_left_zp),
        .o_valid(feed$o_valid),
        .o_value(feed$o_value),
        .o_x(feed$o_x),
        .o_y(feed$o_y),
        .o_pad(feed$o_pad),
        .o_invalid(feed$o_invalid),
        .o_sr(feed$o_sr),
        .o_er(feed$o_er),
        .o_edge(feed$o_edge),
        .o_face(feed$o_face),
        .o_base_x(feed$o_base_x),
        .o_base_y(feed$o_base_y),
        .o_dx_neg(feed$o_dx_neg),
        .o_dx_mag(feed$o_dx_mag),
        .o_dy_neg(feed$o_dy_neg),
        .o_dy_mag(feed$o_dy_mag),
        .gx_neg(feed$gx_neg),
        .gx_mag(feed$gx_mag),
        .gy_neg(feed$gy_neg),
        .gy_mag(feed$gy_mag),
        .gz_neg(feed$gz_neg),
        .gz_mag(feed$gz_mag)
    );
    top$lanes$3$shader shader(
        .clock(shader$clock),
        .host_write(shader$host_write),
        .host_address(shader$host_address),
        .host_data(shader$host_data),
        .value(shader$value),
        .invalid(shader$invalid),
        .at_edge(shader$at_edge),
        .gx_neg(shader$gx_neg),
        .gx_mag(shader$gx_mag),
        .gy_neg(shader$gy_neg),
        .gy_mag(shader$gy_mag),
        .gz_neg(shader$gz_neg),
        .gz_mag(shader$gz_mag),
        .r(shader$r),
        .g(shader$g),
        .b(shader$b),
        .a(shader$a),
        .valid(shader$valid)
    );
    top$lanes$3$ctl ctl(
        .clock(ctl$clock),
        .valid(ctl$valid),
        .er(ctl$er),
        .pad(ctl$pad),
        .base_x(ctl$base_x),
        .base_y(ctl$base_y),
        .face(ctl$face),
        .x(ctl$x),
        .y(ctl$y),
        .sr(ctl$sr),
        .dx_neg(ctl$dx_neg),
        .dx_mag(ctl$dx_mag),
        .dy_neg(ctl$dy_neg),
        .dy_mag(ctl$dy_mag),
        .dims(ctl$dims),
        .coord_mask(ctl$coord_mask),
        .x_t(ctl$x_t),
        .dx_mag_t(ctl$dx_mag_t),
        .dy_mag_t(ctl$dy_mag_t),
        .sel_t$0(ctl$sel_t$0),
        .sel_t$1(ctl$sel_t$1),
        .sel_t$2(ctl$sel_t$2),
        .sel_t$3(ctl$sel_t$3),
        .res_beat(ctl$res_beat),
        .res_valid(ctl$res_valid),
        .px_valid(ctl$px_valid),
        .px_x(ctl$px_x),
        .px_y(ctl$px_y),
        .px_face(ctl$px_face)
    );
    top$lanes$3$taps taps(
        .clock(taps$clock),
        .beats(taps$beats),
        .x(taps$x),
        .res(taps$res),
        .res_beat(taps$res_beat),
        .t0s0(taps$t0s0),
        .t0i1(taps$t0i1),
        .t1s0(taps$t1s0),
        .t1s1(taps$t1s1),
        .t1i1(taps$t1i1),
        .t1i2(taps$t1i2),
        .t3s0(taps$t3s0),
        .t3s1(taps$t3s1),
        .t3i1(taps$t3i1),
        .t3i2(taps$t3i2),
        .t5s0(taps$t5s0),
        .t5s1(taps$t5s1),
        .t5s2(taps$t5s2),
        .t5i1(taps$t5i1),
        .t5i2(taps$t5i2),
        .t5i3(taps$t5i3),
        .t6s0(taps$t6s0),
        .t6i1(taps$t6i1),
        .t7s0(taps$t7s0),
        .t7i1(taps$t7i1),
        .t8s0(taps$t8s0),
        .t8i1(taps$t8i1),
        .t8il(taps$t8il),
        .a$0(taps$a$0),
        .a$1(taps$a$1),
        .a$2(taps$a$2),
        .a$3(taps$a$3),
        .a$4(taps$a$4),
        .a$5(taps$a$5),
        .a$6(taps$a$6),
        .a$7(taps$a$7),
        .a$8(taps$a$8)
    );
    top$lanes$3$cells cells(
        .a$0(cells$a$0),
        .a$1(cells$a$1),
        .a$2(cells$a$2),
        .a$3(cells$a$3),
        .a$4(cells$a$4),
        .a$5(cells$a$5),
        .a$6(cells$a$6),
        .a$7(cells$a$7),
        .a$8(cells$a$8),
        .sel$0(cells$sel$0),
        .sel$1(cells$sel$1),
        .sel$2(cells$sel$2),
        .sel$3(cells$sel$3),
        .c00$0(cells$c00$0),
        .c00$1(cells$c00$1),
        .c00$2(cells$c00$2),
        .c00$3(cells$c00$3),
        .c10$0(cells$c10$0),
        .c10$1(cells$c10$1),
        .c10$2(cells$c10$2),
        .c10$3(cells$c10$3),
        .c01$0(cells$c01$0),
        .c01$1(cells$c01$1),
        .c01$2(cells$c01$2),
        .c01$3(cells$c01$3),
        .c11$0(cells$c11$0),
        .c11$1(cells$c11$1),
        .c11$2(cells$c11$2),
        .c11$3(cells$c11$3),
        .order(cells$order)
    );
    top$lanes$3$bilinear bilinear(
        .clock(bilinear$clock),
        .c00$0(bilinear$c00$0),
        .c00$1(bilinear$c00$1),
        .c00$2(bilinear$c00$2),
        .c00$3(bilinear$c00$3),
        .c10$0(bilinear$c10$0),
        .c10$1(bilinear$c10$1),
        .c10$2(bilinear$c10$2),
        .c10$3(bilinear$c10$3),
        .c01$0(bilinear$c01$0),
        .c01$1(bilinear$c01$1),
        .c01$2(bilinear$c01$2),
        .c01$3(bilinear$c01$3),
        .c11$0(bilinear$c11$0),
        .c11$1(bilinear$c11$1),
        .c11$2(bilinear$c11$2),
        .c11$3(bilinear$c11$3),
        .wx(bilinear$wx),
        .wy(bilinear$wy),
        .out$0(bilinear$out$0),
        .out$1(bilinear$out$1),
        .out$2(bilinear$out$2),
        .out$3(bilinear$out$3)
    );
    top$lanes$3$compositor compositor(
        .clock(compositor$clock),
        .acc_r(compositor$acc_r),
        .acc_g(compositor$acc_g),
        .acc_b(compositor$acc_b),
        .acc_a(compositor$acc_a),
        .new_r(compositor$new_r),
        .new_g(compositor$new_g),
        .new_b(compositor$new_b),
        .new_a(compositor$new_a),
        .new_valid(compositor$new_valid),
        .out_r(compositor$out_r),
        .out_g(compositor$out_g),
        .out_b(compositor$out_b),
        .out_a(compositor$out_a),
        .order(compositor$order)
    );
    
    // Update code
    always @(*) begin
        feed$clock = clock;
        feed$beats = beats;
        feed$beat_valid = beat_valid;
        feed$value = value;
        feed$x = x;
        feed$y = y;
        feed$pad = pad;
        feed$invalid = invalid;
        feed$halo = halo;
        feed$sr = sr;
        feed$er = er;
        feed$base_x = base_x;
        feed$base_y = base_y;
        feed$face = face;
        feed$at_edge = at_edge;
        feed$dx_neg = dx_neg;
        feed$dx_mag = dx_mag;
        feed$dy_neg = dy_neg;
        feed$dy_mag = dy_mag;
        feed$g_from_left_xm = g_from_left_xm;
        feed$g_from_left_ym = g_from_left_ym;
        feed$g_from_left_zm = g_from_left_zm;
        feed$g_from_right_xp = g_from_right_xp;
        feed$g_from_right_yp = g_from_right_yp;
        feed$g_from_right_zp = g_from_right_zp;
        g_to_right_xm = feed$g_to_right_xm;
        g_to_right_ym = feed$g_to_right_ym;
        g_to_right_zm = feed$g_to_right_zm;
        g_to_left_xp = feed$g_to_left_xp;
        g_to_left_yp = feed$g_to_left_yp;
        g_to_left_zp = feed$g_to_left_zp;
        shader$clock = clock;
        shader$host_write = host_write;
        shader$host_address = host_address;
        shader$host_data = host_data;
        shader$value = feed$o_value;
        shader$invalid = feed$o_invalid;
        shader$at_edge = feed$o_edge;
        shader$gx_neg = feed$gx_neg;
        shader$gx_mag = 32'(feed$gx_mag);
        shader$gy_neg = feed$gy_neg;
        shader$gy_mag = 32'(feed$gy_mag);
        shader$gz_neg = feed$gz_neg;
        shader$gz_mag = 32'(feed$gz_mag);
        ctl$clock = clock;
        ctl$valid = feed$o_valid;
        ctl$er = feed$o_er;
        ctl$pad = feed$o_pad;
        ctl$coord_mask = coord_mask;
        ctl$base_x = feed$o_base_x;
        ctl$base_y = feed$o_base_y;
        ctl$face = feed$o_face;
        ctl$x = feed$o_x;
        ctl$y = feed$o_y;
        ctl$sr = feed$o_sr;
        ctl$dx_neg = feed$o_dx_neg;
        ctl$dx_mag = feed$o_dx_mag;
        ctl$dy_neg = feed$o_dy_neg;
        ctl$dy_mag = feed$o_dy_mag;
        ctl$dims = dims;
        taps$clock = clock;
        taps$beats = beats;
        taps$x = ctl$x_t;
        t0s0 = taps$t0s0;
        taps$t0i1 = t0i1;
        t1s0 = taps$t1s0;
        t1s1 = taps$t1s1;
        taps$t1i1 = t1i1;
        taps$t1i2 = t1i2;
        t3s0 = taps$t3s0;
        t3s1 = taps$t3s1;
        taps$t3i1 = t3i1;
        taps$t3i2 = t3i2;
        t5s0 = taps$t5s0;
        t5s1 = taps$t5s1;
        t5s2 = taps$t5s2;
        taps$t5i1 = t5i1;
        taps$t5i2 = t5i2;
        taps$t5i3 = t5i3;
        t6s0 = taps$t6s0;
        taps$t6i1 = t6i1;
        t7s0 = taps$t7s0;
        taps$t7i1 = t7i1;
        t8s0 = taps$t8s0;
        taps$t8i1 = t8i1;
        taps$t8il = t8il;
        cells$a$0 = taps$a$0;
        cells$a$1 = taps$a$1;
        cells$a$2 = taps$a$2;
        cells$a$3 = taps$a$3;
        cells$a$4 = taps$a$4;
        cells$a$5 = taps$a$5;
        cells$a$6 = taps$a$6;
        cells$a$7 = taps$a$7;
        cells$a$8 = taps$a$8;
        cells$order = order;
        cells$sel$0 = ctl$sel_t$0;
        cells$sel$1 = ctl$sel_t$1;
        cells$sel$2 = ctl$sel_t$2;
        cells$sel$3 = ctl$sel_t$3;
        bilinear$clock = clock;
        bilinear$c00$0 = cells$c00$0;
        bilinear$c10$0 = cells$c10$0;
        bilinear$c01$0 = cells$c01$0;
        bilinear$c11$0 = cells$c11$0;
        bilinear$c00$1 = cells$c00$1;
        bilinear$c10$1 = cells$c10$1;
        bilinear$c01$1 = cells$c01$1;
        bilinear$c11$1 = cells$c11$1;
        bilinear$c00$2 = cells$c00$2;
        bilinear$c10$2 = cells$c10$2;
        bilinear$c01$2 = cells$c01$2;
        bilinear$c11$2 = cells$c11$2;
        bilinear$c00$3 = cells$c00$3;
        bilinear$c10$3 = cells$c10$3;
        bilinear$c01$3 = cells$c01$3;
        bilinear$c11$3 = cells$c11$3;
        bilinear$wx = ctl$dx_mag_t;
        bilinear$wy = ctl$dy_mag_t;
        compositor$clock = clock;
        compositor$order = order;
        compositor$acc_r = bilinear$out$0;
        compositor$acc_g = 16'(bilinear$out$1);
        compositor$acc_b = 16'(bilinear$out$2);
        compositor$acc_a = 16'(bilinear$out$3);
        compositor$new_r = shader$r;
        compositor$new_g = shader$g;
        compositor$new_b = shader$b;
        compositor$new_a = shader$a;
        compositor$new_valid = shader$valid;
        res = 64'(compositor$out_r) | (64'(compositor$out_g) << 'h10) | (64'(compositor$out_b) << 'h20) | (64'(compositor$out_a) << 'h30);
        taps$res = res;
        taps$res_beat = ctl$res_beat;
        res_beat = ctl$res_beat;
        res_valid = ctl$res_valid;
        px_valid = ctl$px_valid;
        px_x = ctl$px_x;
        px_y = ctl$px_y;
        px_face = ctl$px_face;
    end
    
endmodule // top$lanes$3
module top$lanes$3$cells(a$0,a$1,a$2,a$3,a$4,a$5,a$6,a$7,a$8,sel$0,sel$1,sel$2,sel$3,c00$0,c00$1,c00$2,c00$3,c10$0,c10$1,c10$2,c10$3,c01$0,c01$1,c01$2,c01$3,c11$0,c11$1,c11$2,c11$3,order);
    
    // Module arguments
    input wire  [63:0] a$0;
    input wire  [63:0] a$1;
    input wire  [63:0] a$2;
    input wire  [63:0] a$3;
    input wire  [63:0] a$4;
    input wire  [63:0] a$5;
    input wire  [63:0] a$6;
    input wire  [63:0] a$7;
    input wire  [63:0] a$8;
    input wire  [6:0] sel$0;
    input wire  [6:0] sel$1;
    input wire  [6:0] sel$2;
    input wire  [6:0] sel$3;
    output reg  [31:0] c00$0;
    output reg  [31:0] c00$1;
    output reg  [31:0] c00$2;
    output reg  [31:0] c00$3;
    output reg  [31:0] c10$0;
    output reg  [31:0] c10$1;
    output reg  [31:0] c10$2;
    output reg  [31:0] c10$3;
    output reg  [31:0] c01$0;
    output reg  [31:0] c01$1;
    output reg  [31:0] c01$2;
    output reg  [31:0] c01$3;
    output reg  [31:0] c11$0;
    output reg  [31:0] c11$1;
    output reg  [31:0] c11$2;
    output reg  [31:0] c11$3;
    input wire  [63:0] order;
    
    // Constant declarations
    localparam  vmax = 64'hff;
    localparam  r_mask = 64'hffff;
    localparam  gba_mask = 64'hffff;
    
    // Local signals
    reg  [63:0] reset;
    reg  [63:0] w00$0;
    reg  [63:0] w00$1;
    reg  [63:0] w00$2;
    reg  [63:0] w00$3;
    reg  [63:0] w10$0;
    reg  [63:0] w10$1;
    reg  [63:0] w10$2;
    reg  [63:0] w10$3;
    reg  [63:0] w01$0;
    reg  [63:0] w01$1;
    reg  [63:0] w01$2;
    reg  [63:0] w01$3;
    reg  [63:0] w11$0;
    reg  [63:0] w11$1;
    reg  [63:0] w11$2;
    reg  [63:0] w11$3;
    
    // Update code
    always @(*) begin
        reset = 'h0;
        if (order['h1]) begin
            reset = vmax;
        end
        w00$0 = a$0;
        w10$0 = a$0;
        w01$0 = a$0;
        if (sel$0['h2]) begin
            if (sel$0['h1]) begin
                w10$0 = a$2;
            end
            else begin
                w10$0 = a$1;
            end
        end
        if (sel$0['h4]) begin
            if (sel$0['h3]) begin
                w01$0 = a$4;
            end
            else begin
                w01$0 = a$3;
            end
        end
        w11$0 = w01$0;
        if (sel$0['h2]) begin
            w11$0 = w10$0;
            if (sel$0['h4]) begin
                if (sel$0['h1]) begin
                    if (sel$0['h3]) begin
                        w11$0 = a$8;
                    end
                    else begin
                        w11$0 = a$6;
                    end
                end
                else if (sel$0['h3]) begin
                    w11$0 = a$7;
                end
                else begin
                    w11$0 = a$5;
                end
            end
        end
        if (sel$0['h5]) begin
            w10$0 = reset;
            w11$0 = reset;
        end
        if (sel$0['h6]) begin
            w01$0 = reset;
            w11$0 = reset;
        end
        if (sel$0['h0]) begin
            w00$0 = reset;
            w10$0 = reset;
            w01$0 = reset;
            w11$0 = reset;
        end
        w00$1 = a$0;
        w10$1 = a$0;
        w01$1 = a$0;
        if (sel$1['h2]) begin
            if (sel$1['h1]) begin
                w10$1 = a$2;
            end
            else begin
                w10$1 = a$1;
            end
        end
        if (sel$1['h4]) begin
            if (sel$1['h3]) begin
                w01$1 = a$4;
            end
            else begin
                w01$1 = a$3;
            end
        end
        w11$1 = w01$1;
        if (sel$1['h2]) begin
            w11$1 = w10$1;
            if (sel$1['h4]) begin
                if (sel$1['h1]) begin
                    if (sel$1['h3]) begin
                        w11$1 = a$8;
                    end
                    else begin
                        w11$1 = a$6;
                    end
                end
                else if (sel$1['h3]) begin
                    w11$1 = a$7;
                end
                else begin
                    w11$1 = a$5;
                end
            end
        end
        if (sel$1['h5]) begin
            w10$1 = reset;
            w11$1 = reset;
        end
        if (sel$1['h6]) begin
            w01$1 = reset;
            w11$1 = reset;
        end
        if (sel$1['h0]) begin
            w00$1 = reset;
            w10$1 = reset;
            w01$1 = reset;
            w11$1 = reset;
        end
        w00$2 = a$0;
        w10$2 = a$0;
        w01$2 = a$0;
        if (sel$2['h2]) begin
            if (sel$2['h1]) begin
                w10$2 = a$2;
            end
            else begin
                w10$2 = a$1;
            end
        end
        if (sel$2['h4]) begin
            if (sel$2['h3]) begin
                w01$2 = a$4;
            end
            else begin
                w01$2 = a$3;
            end
        end
        w11$2 = w01$2;
        if (sel$2['h2]) begin
            w11$2 = w10$2;
            if (sel$2['h4]) begin
                if (sel$2['h1]) begin
                    if (sel$2['h3]) begin
                        w11$2 = a$8;
                    end
                    else begin
                        w11$2 = a$6;
                    end
                end
                else if (sel$2['h3]) begin
                    w11$2 = a$7;
                end
                else begin
                    w11$2 = a$5;
                end
            end
        end
        if (sel$2['h5]) begin
            w10$2 = reset;
            w11$2 = reset;
        end
        if (sel$2['h6]) begin
            w01$2 = reset;
            w11$2 = reset;
        end
        if (sel$2['h0]) begin
            w00$2 = reset;
            w10$2 = reset;
            w01$2 = reset;
            w11$2 = reset;
        end
        w00$3 = a$0;
        w10$3 = a$0;
        w01$3 = a$0;
        if (sel$3['h2]) begin
            if (sel$3['h1]) begin
                w10$3 = a$2;
            end
            else begin
                w10$3 = a$1;
            end
        end
        if (sel$3['h4]) begin
            if (sel$3['h3]) begin
                w01$3 = a$4;
            end
            else begin
                w01$3 = a$3;
            end
        end
        w11$3 = w01$3;
        if (sel$3['h2]) begin
            w11$3 = w10$3;
            if (sel$3['h4]) begin
                if (sel$3['h1]) begin
                    if (sel$3['h3]) begin
                        w11$3 = a$8;
                    end
                    else begin
                        w11$3 = a$6;
                    end
                end
                else if (sel$3['h3]) begin
                    w11$3 = a$7;
                end
                else begin
                    w11$3 = a$5;
                end
            end
        end
        if (sel$3['h5]) begin
            w10$3 = reset;
            w11$3 = reset;
        end
        if (sel$3['h6]) begin
            w01$3 = reset;
            w11$3 = reset;
        end
        if (sel$3['h0]) begin
            w00$3 = reset;
            w10$3 = reset;
            w01$3 = reset;
            w11$3 = reset;
        end
        c00$0 = 32'(w00$0 & r_mask);
        c00$1 = 32'((w00$1 >> 'h10) & gba_mask);
        c00$2 = 32'((w00$2 >> 'h20) & gba_mask);
        c00$3 = 32'((w00$3 >> 'h30) & gba_mask);
        c10$0 = 32'(w10$0 & r_mask);
        c10$1 = 32'((w10$1 >> 'h10) & gba_mask);
        c10$2 = 32'((w10$2 >> 'h20) & gba_mask);
        c10$3 = 32'((w10$3 >> 'h30) & gba_mask);
        c01$0 = 32'(w01$0 & r_mask);
        c01$1 = 32'((w01$1 >> 'h10) & gba_mask);
        c01$2 = 32'((w01$2 >> 'h20) & gba_mask);
        c01$3 = 32'((w01$3 >> 'h30) & gba_mask);
        c11$0 = 32'(w11$0 & r_mask);
        c11$1 = 32'((w11$1 >> 'h10) & gba_mask);
        c11$2 = 32'((w11$2 >> 'h20) & gba_mask);
        c11$3 = 32'((w11$3 >> 'h30) & gba_mask);
    end
    
endmodule // top$lanes$3$cells
module top$lanes$3$ctl(clock,valid,er,pad,base_x,base_y,face,x,y,sr,dx_neg,dx_mag,dy_neg,dy_mag,dims,coord_mask,x_t,dx_mag_t,dy_mag_t,sel_t$0,sel_t$1,sel_t$2,sel_t$3,res_beat,res_valid,px_valid,px_x,px_y,px_face);
    
    // Module arguments
    input wire  clock;
    input wire  valid;
    input wire  er;
    input wire  pad;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  sr;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [63:0] dims;
    input wire  [15:0] coord_mask;
    output reg  [15:0] x_t;
    output reg  [15:0] dx_mag_t;
    output reg  [15:0] dy_mag_t;
    output reg  [6:0] sel_t$0;
    output reg  [6:0] sel_t$1;
    output reg  [6:0] sel_t$2;
    output reg  [6:0] sel_t$3;
    output reg  res_beat;
    output reg  res_valid;
    output reg  px_valid;
    output reg  [15:0] px_x;
    output reg  [15:0] px_y;
    output reg  [2:0] px_face;
    
    // Stub signals
    reg  [15:0] nx_last$d;
    wire  [15:0] nx_last$q;
    reg  nx_last$clock;
    reg  [15:0] ny_last$d;
    wire  [15:0] ny_last$q;
    reg  ny_last$clock;
    reg  [6:0] sel_q$0$d;
    wire  [6:0] sel_q$0$q;
    reg  sel_q$0$clock;
    reg  [6:0] sel_q$1$d;
    wire  [6:0] sel_q$1$q;
    reg  sel_q$1$clock;
    reg  [6:0] sel_q$2$d;
    wire  [6:0] sel_q$2$q;
    reg  sel_q$2$clock;
    reg  [6:0] sel_q$3$d;
    wire  [6:0] sel_q$3$q;
    reg  sel_q$3$clock;
    reg  [15:0] x_q$0$d;
    wire  [15:0] x_q$0$q;
    reg  x_q$0$clock;
    reg  [15:0] x_q$1$d;
    wire  [15:0] x_q$1$q;
    reg  x_q$1$clock;
    reg  [15:0] x_q$2$d;
    wire  [15:0] x_q$2$q;
    reg  x_q$2$clock;
    reg  [15:0] x_q$3$d;
    wire  [15:0] x_q$3$q;
    reg  x_q$3$clock;
    reg  [15:0] x_q$4$d;
    wire  [15:0] x_q$4$q;
    reg  x_q$4$clock;
    reg  [15:0] x_q$5$d;
    wire  [15:0] x_q$5$q;
    reg  x_q$5$clock;
    reg  [15:0] x_q$6$d;
    wire  [15:0] x_q$6$q;
    reg  x_q$6$clock;
    reg  [15:0] x_q$7$d;
    wire  [15:0] x_q$7$q;
    reg  x_q$7$clock;
    reg  [15:0] x_q$8$d;
    wire  [15:0] x_q$8$q;
    reg  x_q$8$clock;
    reg  [15:0] x_q$9$d;
    wire  [15:0] x_q$9$q;
    reg  x_q$9$clock;
    reg  [15:0] y_q$0$d;
    wire  [15:0] y_q$0$q;
    reg  y_q$0$clock;
    reg  [15:0] y_q$1$d;
    wire  [15:0] y_q$1$q;
    reg  y_q$1$clock;
    reg  [15:0] y_q$2$d;
    wire  [15:0] y_q$2$q;
    reg  y_q$2$clock;
    reg  [15:0] y_q$3$d;
    wire  [15:0] y_q$3$q;
    reg  y_q$3$clock;
    reg  [15:0] y_q$4$d;
    wire  [15:0] y_q$4$q;
    reg  y_q$4$clock;
    reg  [15:0] y_q$5$d;
    wire  [15:0] y_q$5$q;
    reg  y_q$5$clock;
    reg  [15:0] y_q$6$d;
    wire  [15:0] y_q$6$q;
    reg  y_q$6$clock;
    reg  [15:0] y_q$7$d;
    wire  [15:0] y_q$7$q;
    reg  y_q$7$clock;
    reg  [15:0] y_q$8$d;
    wire  [15:0] y_q$8$q;
    reg  y_q$8$clock;
    reg  sr_q$0$d;
    wire  sr_q$0$q;
    reg  sr_q$0$clock;
    reg  sr_q$1$d;
    wire  sr_q$1$q;
    reg  sr_q$1$clock;
    reg  sr_q$2$d;
    wire  sr_q$2$q;
    reg  sr_q$2$clock;
    reg  sr_q$3$d;
    wire  sr_q$3$q;
    reg  sr_q$3$clock;
    reg  sr_q$4$d;
    wire  sr_q$4$q;
    reg  sr_q$4$clock;
    reg  sr_q$5$d;
    wire  sr_q$5$q;
    reg  sr_q$5$clock;
    reg  sr_q$6$d;
    wire  sr_q$6$q;
    reg  sr_q$6$clock;
    reg  sr_q$7$d;
    wire  sr_q$7$q;
    reg  sr_q$7$clock;
    reg  sr_q$8$d;
    wire  sr_q$8$q;
    reg  sr_q$8$clock;
    reg  dxn_q$0$d;
    wire  dxn_q$0$q;
    reg  dxn_q$0$clock;
    reg  dxn_q$1$d;
    wire  dxn_q$1$q;
    reg  dxn_q$1$clock;
    reg  dxn_q$2$d;
    wire  dxn_q$2$q;
    reg  dxn_q$2$clock;
    reg  dxn_q$3$d;
    wire  dxn_q$3$q;
    reg  dxn_q$3$clock;
    reg  dxn_q$4$d;
    wire  dxn_q$4$q;
    reg  dxn_q$4$clock;
    reg  dxn_q$5$d;
    wire  dxn_q$5$q;
    reg  dxn_q$5$clock;
    reg  dxn_q$6$d;
    wire  dxn_q$6$q;
    reg  dxn_q$6$clock;
    reg  dxn_q$7$d;
    wire  dxn_q$7$q;
    reg  dxn_q$7$clock;
    reg  dxn_q$8$d;
    wire  dxn_q$8$q;
    reg  dxn_q$8$clock;
    reg  [15:0] dxm_q$0$d;
    wire  [15:0] dxm_q$0$q;
    reg  dxm_q$0$clock;
    reg  [15:0] dxm_q$1$d;
    wire  [15:0] dxm_q$1$q;
    reg  dxm_q$1$clock;
    reg  [15:0] dxm_q$2$d;
    wire  [15:0] dxm_q$2$q;
    reg  dxm_q$2$clock;
    reg  [15:0] dxm_q$3$d;
    wire  [15:0] dxm_q$3$q;
    reg  dxm_q$3$clock;
    reg  [15:0] dxm_q$4$d;
    wire  [15:0] dxm_q$4$q;
    reg  dxm_q$4$clock;
    reg  [15:0] dxm_q$5$d;
    wire  [15:0] dxm_q$5$q;
    reg  dxm_q$5$clock;
    reg  [15:0] dxm_q$6$d;
    wire  [15:0] dxm_q$6$q;
    reg  dxm_q$6$clock;
    reg  [15:0] dxm_q$7$d;
    wire  [15:0] dxm_q$7$q;
    reg  dxm_q$7$clock;
    reg  [15:0] dxm_q$8$d;
    wire  [15:0] dxm_q$8$q;
    reg  dxm_q$8$clock;
    reg  [15:0] dxm_q$9$d;
    wire  [15:0] dxm_q$9$q;
    reg  dxm_q$9$clock;
    reg  dyn_q$0$d;
    wire  dyn_q$0$q;
    reg  dyn_q$0$clock;
    reg  dyn_q$1$d;
    wire  dyn_q$1$q;
    reg  dyn_q$1$clock;
    reg  dyn_q$2$d;
    wire  dyn_q$2$q;
    reg  dyn_q$2$clock;
    reg  dyn_q$3$d;
    wire  dyn_q$3$q;
    reg  dyn_q$3$clock;
    reg  dyn_q$4$d;
    wire  dyn_q$4$q;
    reg  dyn_q$4$clock;
    reg  dyn_q$5$d;
    wire  dyn_q$5$q;
    reg  dyn_q$5$clock;
    reg  dyn_q$6$d;
    wire  dyn_q$6$q;
    reg  dyn_q$6$clock;
    reg  dyn_q$7$d;
    wire  dyn_q$7$q;
    reg  dyn_q$7$clock;
    reg  dyn_q$8$d;
    wire  dyn_q$8$q;
    reg  dyn_q$8$clock;
    reg  [15:0] dym_q$0$d;
    wire  [15:0] dym_q$0$q;
    reg  dym_q$0$clock;
    reg  [15:0] dym_q$1$d;
    wire  [15:0] dym_q$1$q;
    reg  dym_q$1$clock;
    reg  [15:0] dym_q$2$d;
    wire  [15:0] dym_q$2$q;
    reg  dym_q$2$clock;
    reg  [15:0] dym_q$3$d;
    wire  [15:0] dym_q$3$q;
    reg  dym_q$3$clock;
    reg  [15:0] dym_q$4$d;
    wire  [15:0] dym_q$4$q;
    reg  dym_q$4$clock;
    reg  [15:0] dym_q$5$d;
    wire  [15:0] dym_q$5$q;
    reg  dym_q$5$clock;
    reg  [15:0] dym_q$6$d;
    wire  [15:0] dym_q$6$q;
    reg  dym_q$6$clock;
    reg  [15:0] dym_q$7$d;
    wire  [15:0] dym_q$7$q;
    reg  dym_q$7$clock;
    reg  [15:0] dym_q$8$d;
    wire  [15:0] dym_q$8$q;
    reg  dym_q$8$clock;
    reg  [15:0] dym_q$9$d;
    wire  [15:0] dym_q$9$q;
    reg  dym_q$9$clock;
    reg  v_q$0$d;
    wire  v_q$0$q;
    reg  v_q$0$clock;
    reg  v_q$1$d;
    wire  v_q$1$q;
    reg  v_q$1$clock;
    reg  v_q$2$d;
    wire  v_q$2$q;
    reg  v_q$2$clock;
    reg  v_q$3$d;
    wire  v_q$3$q;
    reg  v_q$3$clock;
    reg  v_q$4$d;
    wire  v_q$4$q;
    reg  v_q$4$clock;
    reg  v_q$5$d;
    wire  v_q$5$q;
    reg  v_q$5$clock;
    reg  v_q$6$d;
    wire  v_q$6$q;
    reg  v_q$6$clock;
    reg  v_q$7$d;
    wire  v_q$7$q;
    reg  v_q$7$clock;
    reg  v_q$8$d;
    wire  v_q$8$q;
    reg  v_q$8$clock;
    reg  v_q$9$d;
    wire  v_q$9$q;
    reg  v_q$9$clock;
    reg  v_q$10$d;
    wire  v_q$10$q;
    reg  v_q$10$clock;
    reg  v_q$11$d;
    wire  v_q$11$q;
    reg  v_q$11$clock;
    reg  v_q$12$d;
    wire  v_q$12$q;
    reg  v_q$12$clock;
    reg  v_q$13$d;
    wire  v_q$13$q;
    reg  v_q$13$clock;
    reg  v_q$14$d;
    wire  v_q$14$q;
    reg  v_q$14$clock;
    reg  v_q$15$d;
    wire  v_q$15$q;
    reg  v_q$15$clock;
    reg  v_q$16$d;
    wire  v_q$16$q;
    reg  v_q$16$clock;
    reg  v_q$17$d;
    wire  v_q$17$q;
    reg  v_q$17$clock;
    reg  v_q$18$d;
    wire  v_q$18$q;
    reg  v_q$18$clock;
    reg  v_q$19$d;
    wire  v_q$19$q;
    reg  v_q$19$clock;
    reg  v_q$20$d;
    wire  v_q$20$q;
    reg  v_q$20$clock;
    reg  er_q$0$d;
    wire  er_q$0$q;
    reg  er_q$0$clock;
    reg  er_q$1$d;
    wire  er_q$1$q;
    reg  er_q$1$clock;
    reg  er_q$2$d;
    wire  er_q$2$q;
    reg  er_q$2$clock;
    reg  er_q$3$d;
    wire  er_q$3$q;
    reg  er_q$3$clock;
    reg  er_q$4$d;
    wire  er_q$4$q;
    reg  er_q$4$clock;
    reg  er_q$5$d;
    wire  er_q$5$q;
    reg  er_q$5$clock;
    reg  er_q$6$d;
    wire  er_q$6$q;
    reg  er_q$6$clock;
    reg  er_q$7$d;
    wire  er_q$7$q;
    reg  er_q$7$clock;
    reg  er_q$8$d;
    wire  er_q$8$q;
    reg  er_q$8$clock;
    reg  er_q$9$d;
    wire  er_q$9$q;
    reg  er_q$9$clock;
    reg  er_q$10$d;
    wire  er_q$10$q;
    reg  er_q$10$clock;
    reg  er_q$11$d;
    wire  er_q$11$q;
    reg  er_q$11$clock;
    reg  er_q$12$d;
    wire  er_q$12$q;
    reg  er_q$12$clock;
    reg  er_q$13$d;
    wire  er_q$13$q;
    reg  er_q$13$clock;
    reg  er_q$14$d;
    wire  er_q$14$q;
    reg  er_q$14$clock;
    reg  er_q$15$d;
    wire  er_q$15$q;
    reg  er_q$15$clock;
    reg  er_q$16$d;
    wire  er_q$16$q;
    reg  er_q$16$clock;
    reg  er_q$17$d;
    wire  er_q$17$q;
    reg  er_q$17$clock;
    reg  er_q$18$d;
    wire  er_q$18$q;
    reg  er_q$18$clock;
    reg  er_q$19$d;
    wire  er_q$19$q;
    reg  er_q$19$clock;
    reg  er_q$20$d;
    wire  er_q$20$q;
    reg  er_q$20$clock;
    reg  pad_q$0$d;
    wire  pad_q$0$q;
    reg  pad_q$0$clock;
    reg  pad_q$1$d;
    wire  pad_q$1$q;
    reg  pad_q$1$clock;
    reg  pad_q$2$d;
    wire  pad_q$2$q;
    reg  pad_q$2$clock;
    reg  pad_q$3$d;
    wire  pad_q$3$q;
    reg  pad_q$3$clock;
    reg  pad_q$4$d;
    wire  pad_q$4$q;
    reg  pad_q$4$clock;
    reg  pad_q$5$d;
    wire  pad_q$5$q;
    reg  pad_q$5$clock;
    reg  pad_q$6$d;
    wire  pad_q$6$q;
    reg  pad_q$6$clock;
    reg  pad_q$7$d;
    wire  pad_q$7$q;
    reg  pad_q$7$clock;
    reg  pad_q$8$d;
    wire  pad_q$8$q;
    reg  pad_q$8$clock;
    reg  pad_q$9$d;
    wire  pad_q$9$q;
    reg  pad_q$9$clock;
    reg  pad_q$10$d;
    wire  pad_q$10$q;
    reg  pad_q$10$clock;
    reg  pad_q$11$d;
    wire  pad_q$11$q;
    reg  pad_q$11$clock;
    reg  pad_q$12$d;
    wire  pad_q$12$q;
    reg  pad_q$12$clock;
    reg  pad_q$13$d;
    wire  pad_q$13$q;
    reg  pad_q$13$clock;
    reg  pad_q$14$d;
    wire  pad_q$14$q;
    reg  pad_q$14$clock;
    reg  pad_q$15$d;
    wire  pad_q$15$q;
    reg  pad_q$15$clock;
    reg  pad_q$16$d;
    wire  pad_q$16$q;
    reg  pad_q$16$clock;
    reg  pad_q$17$d;
    wire  pad_q$17$q;
    reg  pad_q$17$clock;
    reg  pad_q$18$d;
    wire  pad_q$18$q;
    reg  pad_q$18$clock;
    reg  pad_q$19$d;
    wire  pad_q$19$q;
    reg  pad_q$19$clock;
    reg  pad_q$20$d;
    wire  pad_q$20$q;
    reg  pad_q$20$clock;
    reg  [15:0] bx_q$0$d;
    wire  [15:0] bx_q$0$q;
    reg  bx_q$0$clock;
    reg  [15:0] bx_q$1$d;
    wire  [15:0] bx_q$1$q;
    reg  bx_q$1$clock;
    reg  [15:0] bx_q$2$d;
    wire  [15:0] bx_q$2$q;
    reg  bx_q$2$clock;
    reg  [15:0] bx_q$3$d;
    wire  [15:0] bx_q$3$q;
    reg  bx_q$3$clock;
    reg  [15:0] bx_q$4$d;
    wire  [15:0] bx_q$4$q;
    reg  bx_q$4$clock;
    reg  [15:0] bx_q$5$d;
    wire  [15:0] bx_q$5$q;
    reg  bx_q$5$clock;
    reg  [15:0] bx_q$6$d;
    wire  [15:0] bx_q$6$q;
    reg  bx_q$6$clock;
    reg  [15:0] bx_q$7$d;
    wire  [15:0] bx_q$7$q;
    reg  bx_q$7$clock;
    reg  [15:0] bx_q$8$d;
    wire  [15:0] bx_q$8$q;
    reg  bx_q$8$clock;
    reg  [15:0] bx_q$9$d;
    wire  [15:0] bx_q$9$q;
    reg  bx_q$9$clock;
    reg  [15:0] bx_q$10$d;
    wire  [15:0] bx_q$10$q;
    reg  bx_q$10$clock;
    reg  [15:0] bx_q$11$d;
    wire  [15:0] bx_q$11$q;
    reg  bx_q$11$clock;
    reg  [15:0] bx_q$12$d;
    wire  [15:0] bx_q$12$q;
    reg  bx_q$12$clock;
    reg  [15:0] bx_q$13$d;
    wire  [15:0] bx_q$13$q;
    reg  bx_q$13$clock;
    reg  [15:0] bx_q$14$d;
    wire  [15:0] bx_q$14$q;
    reg  bx_q$14$clock;
    reg  [15:0] bx_q$15$d;
    wire  [15:0] bx_q$15$q;
    reg  bx_q$15$clock;
    reg  [15:0] bx_q$16$d;
    wire  [15:0] bx_q$16$q;
    reg  bx_q$16$clock;
    reg  [15:0] bx_q$17$d;
    wire  [15:0] bx_q$17$q;
    reg  bx_q$17$clock;
    reg  [15:0] bx_q$18$d;
    wire  [15:0] bx_q$18$q;
    reg  bx_q$18$clock;
    reg  [15:0] bx_q$19$d;
    wire  [15:0] bx_q$19$q;
    reg  bx_q$19$clock;
    reg  [15:0] bx_q$20$d;
    wire  [15:0] bx_q$20$q;
    reg  bx_q$20$clock;
    reg  [15:0] by_q$0$d;
    wire  [15:0] by_q$0$q;
    reg  by_q$0$clock;
    reg  [15:0] by_q$1$d;
    wire  [15:0] by_q$1$q;
    reg  by_q$1$clock;
    reg  [15:0] by_q$2$d;
    wire  [15:0] by_q$2$q;
    reg  by_q$2$clock;
    reg  [15:0] by_q$3$d;
    wire  [15:0] by_q$3$q;
    reg  by_q$3$clock;
    reg  [15:0] by_q$4$d;
    wire  [15:0] by_q$4$q;
    reg  by_q$4$clock;
    reg  [15:0] by_q$5$d;
    wire  [15:0] by_q$5$q;
    reg  by_q$5$clock;
    reg  [15:0] by_q$6$d;
    wire  [15:0] by_q$6$q;
    reg  by_q$6$clock;
    reg  [15:0] by_q$7$d;
    wire  [15:0] by_q$7$q;
    reg  by_q$7$clock;
    reg  [15:0] by_q$8$d;
    wire  [15:0] by_q$8$q;
    reg  by_q$8$clock;
    reg  [15:0] by_q$9$d;
    wire  [15:0] by_q$9$q;
    reg  by_q$9$clock;
    reg  [15:0] by_q$10$d;
    wire  [15:0] by_q$10$q;
    reg  by_q$10$clock;
    reg  [15:0] by_q$11$d;
    wire  [15:0] by_q$11$q;
    reg  by_q$11$clock;
    reg  [15:0] by_q$12$d;
    wire  [15:0] by_q$12$q;
    reg  by_q$12$clock;
    reg  [15:0] by_q$13$d;
    wire  [15:0] by_q$13$q;
    reg  by_q$13$clock;
    reg  [15:0] by_q$14$d;
    wire  [15:0] by_q$14$q;
    reg  by_q$14$clock;
    reg  [15:0] by_q$15$d;
    wire  [15:0] by_q$15$q;
    reg  by_q$15$clock;
    reg  [15:0] by_q$16$d;
    wire  [15:0] by_q$16$q;
    reg  by_q$16$clock;
    reg  [15:0] by_q$17$d;
    wire  [15:0] by_q$17$q;
    reg  by_q$17$clock;
    reg  [15:0] by_q$18$d;
    wire  [15:0] by_q$18$q;
    reg  by_q$18$clock;
    reg  [15:0] by_q$19$d;
    wire  [15:0] by_q$19$q;
    reg  by_q$19$clock;
    reg  [15:0] by_q$20$d;
    wire  [15:0] by_q$20$q;
    reg  by_q$20$clock;
    reg  [2:0] face_q$0$d;
    wire  [2:0] face_q$0$q;
    reg  face_q$0$clock;
    reg  [2:0] face_q$1$d;
    wire  [2:0] face_q$1$q;
    reg  face_q$1$clock;
    reg  [2:0] face_q$2$d;
    wire  [2:0] face_q$2$q;
    reg  face_q$2$clock;
    reg  [2:0] face_q$3$d;
    wire  [2:0] face_q$3$q;
    reg  face_q$3$clock;
    reg  [2:0] face_q$4$d;
    wire  [2:0] face_q$4$q;
    reg  face_q$4$clock;
    reg  [2:0] face_q$5$d;
    wire  [2:0] face_q$5$q;
    reg  face_q$5$clock;
    reg  [2:0] face_q$6$d;
    wire  [2:0] face_q$6$q;
    reg  face_q$6$clock;
    reg  [2:0] face_q$7$d;
    wire  [2:0] face_q$7$q;
    reg  face_q$7$clock;
    reg  [2:0] face_q$8$d;
    wire  [2:0] face_q$8$q;
    reg  face_q$8$clock;
    reg  [2:0] face_q$9$d;
    wire  [2:0] face_q$9$q;
    reg  face_q$9$clock;
    reg  [2:0] face_q$10$d;
    wire  [2:0] face_q$10$q;
    reg  face_q$10$clock;
    reg  [2:0] face_q$11$d;
    wire  [2:0] face_q$11$q;
    reg  face_q$11$clock;
    reg  [2:0] face_q$12$d;
    wire  [2:0] face_q$12$q;
    reg  face_q$12$clock;
    reg  [2:0] face_q$13$d;
    wire  [2:0] face_q$13$q;
    reg  face_q$13$clock;
    reg  [2:0] face_q$14$d;
    wire  [2:0] face_q$14$q;
    reg  face_q$14$clock;
    reg  [2:0] face_q$15$d;
    wire  [2:0] face_q$15$q;
    reg  face_q$15$clock;
    reg  [2:0] face_q$16$d;
    wire  [2:0] face_q$16$q;
    reg  face_q$16$clock;
    reg  [2:0] face_q$17$d;
    wire  [2:0] face_q$17$q;
    reg  face_q$17$clock;
    reg  [2:0] face_q$18$d;
    wire  [2:0] face_q$18$q;
    reg  face_q$18$clock;
    reg  [2:0] face_q$19$d;
    wire  [2:0] face_q$19$q;
    reg  face_q$19$clock;
    reg  [2:0] face_q$20$d;
    wire  [2:0] face_q$20$q;
    reg  face_q$20$clock;
    
    // Local signals
    reg  x_out;
    reg  y_out;
    reg  dx_nz;
    reg  dy_nz;
    reg  [6:0] sel;
    
    // Sub module instances
    top$lanes$3$ctl$nx_last nx_last(
        .d(nx_last$d),
        .q(nx_last$q),
        .clock(nx_last$clock)
    );
    top$lanes$3$ctl$ny_last ny_last(
        .d(ny_last$d),
        .q(ny_last$q),
        .clock(ny_last$clock)
    );
    top$lanes$3$ctl$sel_q$0 sel_q$0(
        .d(sel_q$0$d),
        .q(sel_q$0$q),
        .clock(sel_q$0$clock)
    );
    top$lanes$3$ctl$sel_q$1 sel_q$1(
        .d(sel_q$1$d),
        .q(sel_q$1$q),
        .clock(sel_q$1$clock)
    );
    top$lanes$3$ctl$sel_q$2 sel_q$2(
        .d(sel_q$2$d),
        .q(sel_q$2$q),
        .clock(sel_q$2$clock)
    );
    top$lanes$3$ctl$sel_q$3 sel_q$3(
        .d(sel_q$3$d),
        .q(sel_q$3$q),
        .clock(sel_q$3$clock)
    );
    top$lanes$3$ctl$x_q$0 x_q$0(
        .d(x_q$0$d),
        .q(x_q$0$q),
        .clock(x_q$0$clock)
    );
    top$lanes$3$ctl$x_q$1 x_q$1(
        .d(x_q$1$d),
        .q(x_q$1$q),
        .clock(x_q$1$clock)
    );
    top$lanes$3$ctl$x_q$2 x_q$2(
        .d(x_q$2$d),
        .q(x_q$2$q),
        .clock(x_q$2$clock)
    );
    top$lanes$3$ctl$x_q$3 x_q$3(
        .d(x_q$3$d),
        .q(x_q$3$q),
        .clock(x_q$3$clock)
    );
    top$lanes$3$ctl$x_q$4 x_q$4(
        .d(x_q$4$d),
        .q(x_q$4$q),
        .clock(x_q$4$clock)
    );
    top$lanes$3$ctl$x_q$5 x_q$5(
        .d(x_q$5$d),
        .q(x_q$5$q),
        .clock(x_q$5$clock)
    );
    top$lanes$3$ctl$x_q$6 x_q$6(
        .d(x_q$6$d),
        .q(x_q$6$q),
        .clock(x_q$6$clock)
    );
    top$lanes$3$ctl$x_q$7 x_q$7(
        .d(x_q$7$d),
        .q(x_q$7$q),
        .clock(x_q$7$clock)
    );
    top$lanes$3$ctl$x_q$8 x_q$8(
        .d(x_q$8$d),
        .q(x_q$8$q),
        .clock(x_q$8$clock)
    );
    top$lanes$3$ctl$x_q$9 x_q$9(
        .d(x_q$9$d),
        .q(x_q$9$q),
        .clock(x_q$9$clock)
    );
    top$lanes$3$ctl$y_q$0 y_q$0(
        .d(y_q$0$d),
        .q(y_q$0$q),
        .clock(y_q$0$clock)
    );
    top$lanes$3$ctl$y_q$1 y_q$1(
        .d(y_q$1$d),
        .q(y_q$1$q),
        .clock(y_q$1$clock)
    );
    top$lanes$3$ctl$y_q$2 y_q$2(
        .d(y_q$2$d),
        .q(y_q$2$q),
        .clock(y_q$2$clock)
    );
    top$lanes$3$ctl$y_q$3 y_q$3(
        .d(y_q$3$d),
        .q(y_q$3$q),
        .clock(y_q$3$clock)
    );
    top$lanes$3$ctl$y_q$4 y_q$4(
        .d(y_q$4$d),
        .q(y_q$4$q),
        .clock(y_q$4$clock)
    );
    top$lanes$3$ctl$y_q$5 y_q$5(
        .d(y_q$5$d),
        .q(y_q$5$q),
        .clock(y_q$5$clock)
    );
    top$lanes$3$ctl$y_q$6 y_q$6(
        .d(y_q$6$d),
        .q(y_q$6$q),
        .clock(y_q$6$clock)
    );
    top$lanes$3$ctl$y_q$7 y_q$7(
        .d(y_q$7$d),
        .q(y_q$7$q),
        .clock(y_q$7$clock)
    );
    top$lanes$3$ctl$y_q$8 y_q$8(
        .d(y_q$8$d),
        .q(y_q$8$q),
        .clock(y_q$8$clock)
    );
    top$lanes$3$ctl$sr_q$0 sr_q$0(
        .d(sr_q$0$d),
        .q(sr_q$0$q),
        .clock(sr_q$0$clock)
    );
    top$lanes$3$ctl$sr_q$1 sr_q$1(
        .d(sr_q$1$d),
        .q(sr_q$1$q),
        .clock(sr_q$1$clock)
    );
    top$lanes$3$ctl$sr_q$2 sr_q$2(
        .d(sr_q$2$d),
        .q(sr_q$2$q),
        .clock(sr_q$2$clock)
    );
    top$lanes$3$ctl$sr_q$3 sr_q$3(
        .d(sr_q$3$d),
        .q(sr_q$3$q),
        .clock(sr_q$3$clock)
    );
    top$lanes$3$ctl$sr_q$4 sr_q$4(
        .d(sr_q$4$d),
        .q(sr_q$4$q),
        .clock(sr_q$4$clock)
    );
    top$lanes$3$ctl$sr_q$5 sr_q$5(
        .d(sr_q$5$d),
        .q(sr_q$5$q),
        .clock(sr_q$5$clock)
    );
    top$lanes$3$ctl$sr_q$6 sr_q$6(
        .d(sr_q$6$d),
        .q(sr_q$6$q),
        .clock(sr_q$6$clock)
    );
    top$lanes$3$ctl$sr_q$7 sr_q$7(
        .d(sr_q$7$d),
        .q(sr_q$7$q),
        .clock(sr_q$7$clock)
    );
    top$lanes$3$ctl$sr_q$8 sr_q$8(
        .d(sr_q$8$d),
        .q(sr_q$8$q),
        .clock(sr_q$8$clock)
    );
    top$lanes$3$ctl$dxn_q$0 dxn_q$0(
        .d(dxn_q$0$d),
        .q(dxn_q$0$q),
        .clock(dxn_q$0$clock)
    );
    top$lanes$3$ctl$dxn_q$1 dxn_q$1(
        .d(dxn_q$1$d),
        .q(dxn_q$1$q),
        .clock(dxn_q$1$clock)
    );
    top$lanes$3$ctl$dxn_q$2 dxn_q$2(
        .d(dxn_q$2$d),
        .q(dxn_q$2$q),
        .clock(dxn_q$2$clock)
    );
    top$lanes$3$ctl$dxn_q$3 dxn_q$3(
        .d(dxn_q$3$d),
        .q(dxn_q$3$q),
        .clock(dxn_q$3$clock)
    );
    top$lanes$3$ctl$dxn_q$4 dxn_q$4(
        .d(dxn_q$4$d),
        .q(dxn_q$4$q),
        .clock(dxn_q$4$clock)
    );
    top$lanes$3$ctl$dxn_q$5 dxn_q$5(
        .d(dxn_q$5$d),
        .q(dxn_q$5$q),
        .clock(dxn_q$5$clock)
    );
    top$lanes$3$ctl$dxn_q$6 dxn_q$6(
        .d(dxn_q$6$d),
        .q(dxn_q$6$q),
        .clock(dxn_q$6$clock)
    );
    top$lanes$3$ctl$dxn_q$7 dxn_q$7(
        .d(dxn_q$7$d),
        .q(dxn_q$7$q),
        .clock(dxn_q$7$clock)
    );
    top$lanes$3$ctl$dxn_q$8 dxn_q$8(
        .d(dxn_q$8$d),
        .q(dxn_q$8$q),
        .clock(dxn_q$8$clock)
    );
    top$lanes$3$ctl$dxm_q$0 dxm_q$0(
        .d(dxm_q$0$d),
        .q(dxm_q$0$q),
        .clock(dxm_q$0$clock)
    );
    top$lanes$3$ctl$dxm_q$1 dxm_q$1(
        .d(dxm_q$1$d),
        .q(dxm_q$1$q),
        .clock(dxm_q$1$clock)
    );
    top$lanes$3$ctl$dxm_q$2 dxm_q$2(
        .d(dxm_q$2$d),
        .q(dxm_q$2$q),
        .clock(dxm_q$2$clock)
    );
    top$lanes$3$ctl$dxm_q$3 dxm_q$3(
        .d(dxm_q$3$d),
        .q(dxm_q$3$q),
        .clock(dxm_q$3$clock)
    );
    top$lanes$3$ctl$dxm_q$4 dxm_q$4(
        .d(dxm_q$4$d),
        .q(dxm_q$4$q),
        .clock(dxm_q$4$clock)
    );
    top$lanes$3$ctl$dxm_q$5 dxm_q$5(
        .d(dxm_q$5$d),
        .q(dxm_q$5$q),
        .clock(dxm_q$5$clock)
    );
    top$lanes$3$ctl$dxm_q$6 dxm_q$6(
        .d(dxm_q$6$d),
        .q(dxm_q$6$q),
        .clock(dxm_q$6$clock)
    );
    top$lanes$3$ctl$dxm_q$7 dxm_q$7(
        .d(dxm_q$7$d),
        .q(dxm_q$7$q),
        .clock(dxm_q$7$clock)
    );
    top$lanes$3$ctl$dxm_q$8 dxm_q$8(
        .d(dxm_q$8$d),
        .q(dxm_q$8$q),
        .clock(dxm_q$8$clock)
    );
    top$lanes$3$ctl$dxm_q$9 dxm_q$9(
        .d(dxm_q$9$d),
        .q(dxm_q$9$q),
        .clock(dxm_q$9$clock)
    );
    top$lanes$3$ctl$dyn_q$0 dyn_q$0(
        .d(dyn_q$0$d),
        .q(dyn_q$0$q),
        .clock(dyn_q$0$clock)
    );
    top$lanes$3$ctl$dyn_q$1 dyn_q$1(
        .d(dyn_q$1$d),
        .q(dyn_q$1$q),
        .clock(dyn_q$1$clock)
    );
    top$lanes$3$ctl$dyn_q$2 dyn_q$2(
        .d(dyn_q$2$d),
        .q(dyn_q$2$q),
        .clock(dyn_q$2$clock)
    );
    top$lanes$3$ctl$dyn_q$3 dyn_q$3(
        .d(dyn_q$3$d),
        .q(dyn_q$3$q),
        .clock(dyn_q$3$clock)
    );
    top$lanes$3$ctl$dyn_q$4 dyn_q$4(
        .d(dyn_q$4$d),
        .q(dyn_q$4$q),
        .clock(dyn_q$4$clock)
    );
    top$lanes$3$ctl$dyn_q$5 dyn_q$5(
        .d(dyn_q$5$d),
        .q(dyn_q$5$q),
        .clock(dyn_q$5$clock)
    );
    top$lanes$3$ctl$dyn_q$6 dyn_q$6(
        .d(dyn_q$6$d),
        .q(dyn_q$6$q),
        .clock(dyn_q$6$clock)
    );
    top$lanes$3$ctl$dyn_q$7 dyn_q$7(
        .d(dyn_q$7$d),
        .q(dyn_q$7$q),
        .clock(dyn_q$7$clock)
    );
    top$lanes$3$ctl$dyn_q$8 dyn_q$8(
        .d(dyn_q$8$d),
        .q(dyn_q$8$q),
        .clock(dyn_q$8$clock)
    );
    top$lanes$3$ctl$dym_q$0 dym_q$0(
        .d(dym_q$0$d),
        .q(dym_q$0$q),
        .clock(dym_q$0$clock)
    );
    top$lanes$3$ctl$dym_q$1 dym_q$1(
        .d(dym_q$1$d),
        .q(dym_q$1$q),
        .clock(dym_q$1$clock)
    );
    top$lanes$3$ctl$dym_q$2 dym_q$2(
        .d(dym_q$2$d),
        .q(dym_q$2$q),
        .clock(dym_q$2$clock)
    );
    top$lanes$3$ctl$dym_q$3 dym_q$3(
        .d(dym_q$3$d),
        .q(dym_q$3$q),
        .clock(dym_q$3$clock)
    );
    top$lanes$3$ctl$dym_q$4 dym_q$4(
        .d(dym_q$4$d),
        .q(dym_q$4$q),
        .clock(dym_q$4$clock)
    );
    top$lanes$3$ctl$dym_q$5 dym_q$5(
        .d(dym_q$5$d),
        .q(dym_q$5$q),
        .clock(dym_q$5$clock)
    );
    top$lanes$3$ctl$dym_q$6 dym_q$6(
        .d(dym_q$6$d),
        .q(dym_q$6$q),
        .clock(dym_q$6$clock)
    );
    top$lanes$3$ctl$dym_q$7 dym_q$7(
        .d(dym_q$7$d),
        .q(dym_q$7$q),
        .clock(dym_q$7$clock)
    );
    top$lanes$3$ctl$dym_q$8 dym_q$8(
        .d(dym_q$8$d),
        .q(dym_q$8$q),
        .clock(dym_q$8$clock)
    );
    top$lanes$3$ctl$dym_q$9 dym_q$9(
        .d(dym_q$9$d),
        .q(dym_q$9$q),
        .clock(dym_q$9$clock)
    );
    top$lanes$3$ctl$v_q$0 v_q$0(
        .d(v_q$0$d),
        .q(v_q$0$q),
        .clock(v_q$0$clock)
    );
    top$lanes$3$ctl$v_q$1 v_q$1(
        .d(v_q$1$d),
        .q(v_q$1$q),
        .clock(v_q$1$clock)
    );
    top$lanes$3$ctl$v_q$2 v_q$2(
        .d(v_q$2$d),
        .q(v_q$2$q),
        .clock(v_q$2$clock)
    );
    top$lanes$3$ctl$v_q$3 v_q$3(
        .d(v_q$3$d),
        .q(v_q$3$q),
        .clock(v_q$3$clock)
    );
    top$lanes$3$ctl$v_q$4 v_q$4(
        .d(v_q$4$d),
        .q(v_q$4$q),
        .clock(v_q$4$clock)
    );
    top$lanes$3$ctl$v_q$5 v_q$5(
        .d(v_q$5$d),
        .q(v_q$5$q),
        .clock(v_q$5$clock)
    );
    top$lanes$3$ctl$v_q$6 v_q$6(
        .d(v_q$6$d),
        .q(v_q$6$q),
        .clock(v_q$6$clock)
    );
    top$lanes$3$ctl$v_q$7 v_q$7(
        .d(v_q$7$d),
        .q(v_q$7$q),
        .clock(v_q$7$clock)
    );
    top$lanes$3$ctl$v_q$8 v_q$8(
        .d(v_q$8$d),
        .q(v_q$8$q),
        .clock(v_q$8$clock)
    );
    top$lanes$3$ctl$v_q$9 v_q$9(
        .d(v_q$9$d),
        .q(v_q$9$q),
        .clock(v_q$9$clock)
    );
    top$lanes$3$ctl$v_q$10 v_q$10(
        .d(v_q$10$d),
        .q(v_q$10$q),
        .clock(v_q$10$clock)
    );
    top$lanes$3$ctl$v_q$11 v_q$11(
        .d(v_q$11$d),
        .q(v_q$11$q),
        .clock(v_q$11$clock)
    );
    top$lanes$3$ctl$v_q$12 v_q$12(
        .d(v_q$12$d),
        .q(v_q$12$q),
        .clock(v_q$12$clock)
    );
    top$lanes$3$ctl$v_q$13 v_q$13(
        .d(v_q$13$d),
        .q(v_q$13$q),
        .clock(v_q$13$clock)
    );
    top$lanes$3$ctl$v_q$14 v_q$14(
        .d(v_q$14$d),
        .q(v_q$14$q),
        .clock(v_q$14$clock)
    );
    top$lanes$3$ctl$v_q$15 v_q$15(
        .d(v_q$15$d),
        .q(v_q$15$q),
        .clock(v_q$15$clock)
    );
    top$lanes$3$ctl$v_q$16 v_q$16(
        .d(v_q$16$d),
        .q(v_q$16$q),
        .clock(v_q$16$clock)
    );
    top$lanes$3$ctl$v_q$17 v_q$17(
        .d(v_q$17$d),
        .q(v_q$17$q),
        .clock(v_q$17$clock)
    );
    top$lanes$3$ctl$v_q$18 v_q$18(
        .d(v_q$18$d),
        .q(v_q$18$q),
        .clock(v_q$18$clock)
    );
    top$lanes$3$ctl$v_q$19 v_q$19(
        .d(v_q$19$d),
        .q(v_q$19$q),
        .clock(v_q$19$clock)
    );
    top$lanes$3$ctl$v_q$20 v_q$20(
        .d(v_q$20$d),
        .q(v_q$20$q),
        .clock(v_q$20$clock)
    );
    top$lanes$3$ctl$er_q$0 er_q$0(
        .d(er_q$0$d),
        .q(er_q$0$q),
        .clock(er_q$0$clock)
    );
    top$lanes$3$ctl$er_q$1 er_q$1(
        .d(er_q$1$d),
        .q(er_q$1$q),
        .clock(er_q$1$clock)
    );
    top$lanes$3$ctl$er_q$2 er_q$2(
        .d(er_q$2$d),
        .q(er_q$2$q),
        .clock(er_q$2$clock)
    );
    top$lanes$3$ctl$er_q$3 er_q$3(
        .d(er_q$3$d),
        .q(er_q$3$q),
        .clock(er_q$3$clock)
    );
    top$lanes$3$ctl$er_q$4 er_q$4(
        .d(er_q$4$d),
        .q(er_q$4$q),
        .clock(er_q$4$clock)
    );
    top$lanes$3$ctl$er_q$5 er_q$5(
        .d(er_q$5$d),
        .q(er_q$5$q),
        .clock(er_q$5$clock)
    );
    top$lanes$3$ctl$er_q$6 er_q$6(
        .d(er_q$6$d),
        .q(er_q$6$q),
        .clock(er_q$6$clock)
    );
    top$lanes$3$ctl$er_q$7 er_q$7(
        .d(er_q$7$d),
        .q(er_q$7$q),
        .clock(er_q$7$clock)
    );
    top$lanes$3$ctl$er_q$8 er_q$8(
        .d(er_q$8$d),
        .q(er_q$8$q),
        .clock(er_q$8$clock)
    );
    top$lanes$3$ctl$er_q$9 er_q$9(
        .d(er_q$9$d),
        .q(er_q$9$q),
        .clock(er_q$9$clock)
    );
    top$lanes$3$ctl$er_q$10 er_q$10(
        .d(er_q$10$d),
        .q(er_q$10$q),
        .clock(er_q$10$clock)
    );
    top$lanes$3$ctl$er_q$11 er_q$11(
        .d(er_q$11$d),
        .q(er_q$11$q),
        .clock(er_q$11$clock)
    );
    top$lanes$3$ctl$er_q$12 er_q$12(
        .d(er_q$12$d),
        .q(er_q$12$q),
        .clock(er_q$12$clock)
    );
    top$lanes$3$ctl$er_q$13 er_q$13(
        .d(er_q$13$d),
        .q(er_q$13$q),
        .clock(er_q$13$clock)
    );
    top$lanes$3$ctl$er_q$14 er_q$14(
        .d(er_q$14$d),
        .q(er_q$14$q),
        .clock(er_q$14$clock)
    );
    top$lanes$3$ctl$er_q$15 er_q$15(
        .d(er_q$15$d),
        .q(er_q$15$q),
        .clock(er_q$15$clock)
    );
    top$lanes$3$ctl$er_q$16 er_q$16(
        .d(er_q$16$d),
        .q(er_q$16$q),
        .clock(er_q$16$clock)
    );
    top$lanes$3$ctl$er_q$17 er_q$17(
        .d(er_q$17$d),
        .q(er_q$17$q),
        .clock(er_q$17$clock)
    );
    top$lanes$3$ctl$er_q$18 er_q$18(
        .d(er_q$18$d),
        .q(er_q$18$q),
        .clock(er_q$18$clock)
    );
    top$lanes$3$ctl$er_q$19 er_q$19(
        .d(er_q$19$d),
        .q(er_q$19$q),
        .clock(er_q$19$clock)
    );
    top$lanes$3$ctl$er_q$20 er_q$20(
        .d(er_q$20$d),
        .q(er_q$20$q),
        .clock(er_q$20$clock)
    );
    top$lanes$3$ctl$pad_q$0 pad_q$0(
        .d(pad_q$0$d),
        .q(pad_q$0$q),
        .clock(pad_q$0$clock)
    );
    top$lanes$3$ctl$pad_q$1 pad_q$1(
        .d(pad_q$1$d),
        .q(pad_q$1$q),
        .clock(pad_q$1$clock)
    );
    top$lanes$3$ctl$pad_q$2 pad_q$2(
        .d(pad_q$2$d),
        .q(pad_q$2$q),
        .clock(pad_q$2$clock)
    );
    top$lanes$3$ctl$pad_q$3 pad_q$3(
        .d(pad_q$3$d),
        .q(pad_q$3$q),
        .clock(pad_q$3$clock)
    );
    top$lanes$3$ctl$pad_q$4 pad_q$4(
        .d(pad_q$4$d),
        .q(pad_q$4$q),
        .clock(pad_q$4$clock)
    );
    top$lanes$3$ctl$pad_q$5 pad_q$5(
        .d(pad_q$5$d),
        .q(pad_q$5$q),
        .clock(pad_q$5$clock)
    );
    top$lanes$3$ctl$pad_q$6 pad_q$6(
        .d(pad_q$6$d),
        .q(pad_q$6$q),
        .clock(pad_q$6$clock)
    );
    top$lanes$3$ctl$pad_q$7 pad_q$7(
        .d(pad_q$7$d),
        .q(pad_q$7$q),
        .clock(pad_q$7$clock)
    );
    top$lanes$3$ctl$pad_q$8 pad_q$8(
        .d(pad_q$8$d),
        .q(pad_q$8$q),
        .clock(pad_q$8$clock)
    );
    top$lanes$3$ctl$pad_q$9 pad_q$9(
        .d(pad_q$9$d),
        .q(pad_q$9$q),
        .clock(pad_q$9$clock)
    );
    top$lanes$3$ctl$pad_q$10 pad_q$10(
        .d(pad_q$10$d),
        .q(pad_q$10$q),
        .clock(pad_q$10$clock)
    );
    top$lanes$3$ctl$pad_q$11 pad_q$11(
        .d(pad_q$11$d),
        .q(pad_q$11$q),
        .clock(pad_q$11$clock)
    );
    top$lanes$3$ctl$pad_q$12 pad_q$12(
        .d(pad_q$12$d),
        .q(pad_q$12$q),
        .clock(pad_q$12$clock)
    );
    top$lanes$3$ctl$pad_q$13 pad_q$13(
        .d(pad_q$13$d),
        .q(pad_q$13$q),
        .clock(pad_q$13$clock)
    );
    top$lanes$3$ctl$pad_q$14 pad_q$14(
        .d(pad_q$14$d),
        .q(pad_q$14$q),
        .clock(pad_q$14$clock)
    );
    top$lanes$3$ctl$pad_q$15 pad_q$15(
        .d(pad_q$15$d),
        .q(pad_q$15$q),
        .clock(pad_q$15$clock)
    );
    top$lanes$3$ctl$pad_q$16 pad_q$16(
        .d(pad_q$16$d),
        .q(pad_q$16$q),
        .clock(pad_q$16$clock)
    );
    top$lanes$3$ctl$pad_q$17 pad_q$17(
        .d(pad_q$17$d),
        .q(pad_q$17$q),
        .clock(pad_q$17$clock)
    );
    top$lanes$3$ctl$pad_q$18 pad_q$18(
        .d(pad_q$18$d),
        .q(pad_q$18$q),
        .clock(pad_q$18$clock)
    );
    top$lanes$3$ctl$pad_q$19 pad_q$19(
        .d(pad_q$19$d),
        .q(pad_q$19$q),
        .clock(pad_q$19$clock)
    );
    top$lanes$3$ctl$pad_q$20 pad_q$20(
        .d(pad_q$20$d),
        .q(pad_q$20$q),
        .clock(pad_q$20$clock)
    );
    top$lanes$3$ctl$bx_q$0 bx_q$0(
        .d(bx_q$0$d),
        .q(bx_q$0$q),
        .clock(bx_q$0$clock)
    );
    top$lanes$3$ctl$bx_q$1 bx_q$1(
        .d(bx_q$1$d),
        .q(bx_q$1$q),
        .clock(bx_q$1$clock)
    );
    top$lanes$3$ctl$bx_q$2 bx_q$2(
        .d(bx_q$2$d),
        .q(bx_q$2$q),
        .clock(bx_q$2$clock)
    );
    top$lanes$3$ctl$bx_q$3 bx_q$3(
        .d(bx_q$3$d),
        .q(bx_q$3$q),
        .clock(bx_q$3$clock)
    );
    top$lanes$3$ctl$bx_q$4 bx_q$4(
        .d(bx_q$4$d),
        .q(bx_q$4$q),
        .clock(bx_q$4$clock)
    );
    top$lanes$3$ctl$bx_q$5 bx_q$5(
        .d(bx_q$5$d),
        .q(bx_q$5$q),
        .clock(bx_q$5$clock)
    );
    top$lanes$3$ctl$bx_q$6 bx_q$6(
        .d(bx_q$6$d),
        .q(bx_q$6$q),
        .clock(bx_q$6$clock)
    );
    top$lanes$3$ctl$bx_q$7 bx_q$7(
        .d(bx_q$7$d),
        .q(bx_q$7$q),
        .clock(bx_q$7$clock)
    );
    top$lanes$3$ctl$bx_q$8 bx_q$8(
        .d(bx_q$8$d),
        .q(bx_q$8$q),
        .clock(bx_q$8$clock)
    );
    top$lanes$3$ctl$bx_q$9 bx_q$9(
        .d(bx_q$9$d),
        .q(bx_q$9$q),
        .clock(bx_q$9$clock)
    );
    top$lanes$3$ctl$bx_q$10 bx_q$10(
        .d(bx_q$10$d),
        .q(bx_q$10$q),
        .clock(bx_q$10$clock)
    );
    top$lanes$3$ctl$bx_q$11 bx_q$11(
        .d(bx_q$11$d),
        .q(bx_q$11$q),
        .clock(bx_q$11$clock)
    );
    top$lanes$3$ctl$bx_q$12 bx_q$12(
        .d(bx_q$12$d),
        .q(bx_q$12$q),
        .clock(bx_q$12$clock)
    );
    top$lanes$3$ctl$bx_q$13 bx_q$13(
        .d(bx_q$13$d),
        .q(bx_q$13$q),
        .clock(bx_q$13$clock)
    );
    top$lanes$3$ctl$bx_q$14 bx_q$14(
        .d(bx_q$14$d),
        .q(bx_q$14$q),
        .clock(bx_q$14$clock)
    );
    top$lanes$3$ctl$bx_q$15 bx_q$15(
        .d(bx_q$15$d),
        .q(bx_q$15$q),
        .clock(bx_q$15$clock)
    );
    top$lanes$3$ctl$bx_q$16 bx_q$16(
        .d(bx_q$16$d),
        .q(bx_q$16$q),
        .clock(bx_q$16$clock)
    );
    top$lanes$3$ctl$bx_q$17 bx_q$17(
        .d(bx_q$17$d),
        .q(bx_q$17$q),
        .clock(bx_q$17$clock)
    );
    top$lanes$3$ctl$bx_q$18 bx_q$18(
        .d(bx_q$18$d),
        .q(bx_q$18$q),
        .clock(bx_q$18$clock)
    );
    top$lanes$3$ctl$bx_q$19 bx_q$19(
        .d(bx_q$19$d),
        .q(bx_q$19$q),
        .clock(bx_q$19$clock)
    );
    top$lanes$3$ctl$bx_q$20 bx_q$20(
        .d(bx_q$20$d),
        .q(bx_q$20$q),
        .clock(bx_q$20$clock)
    );
    top$lanes$3$ctl$by_q$0 by_q$0(
        .d(by_q$0$d),
        .q(by_q$0$q),
        .clock(by_q$0$clock)
    );
    top$lanes$3$ctl$by_q$1 by_q$1(
        .d(by_q$1$d),
        .q(by_q$1$q),
        .clock(by_q$1$clock)
    );
    top$lanes$3$ctl$by_q$2 by_q$2(
        .d(by_q$2$d),
        .q(by_q$2$q),
        .clock(by_q$2$clock)
    );
    top$lanes$3$ctl$by_q$3 by_q$3(
        .d(by_q$3$d),
        .q(by_q$3$q),
        .clock(by_q$3$clock)
    );
    top$lanes$3$ctl$by_q$4 by_q$4(
        .d(by_q$4$d),
        .q(by_q$4$q),
        .clock(by_q$4$clock)
    );
    top$lanes$3$ctl$by_q$5 by_q$5(
        .d(by_q$5$d),
        .q(by_q$5$q),
        .clock(by_q$5$clock)
    );
    top$lanes$3$ctl$by_q$6 by_q$6(
        .d(by_q$6$d),
        .q(by_q$6$q),
        .clock(by_q$6$clock)
    );
    top$lanes$3$ctl$by_q$7 by_q$7(
        .d(by_q$7$d),
        .q(by_q$7$q),
        .clock(by_q$7$clock)
    );
    top$lanes$3$ctl$by_q$8 by_q$8(
        .d(by_q$8$d),
        .q(by_q$8$q),
        .clock(by_q$8$clock)
    );
    top$lanes$3$ctl$by_q$9 by_q$9(
        .d(by_q$9$d),
        .q(by_q$9$q),
        .clock(by_q$9$clock)
    );
    top$lanes$3$ctl$by_q$10 by_q$10(
        .d(by_q$10$d),
        .q(by_q$10$q),
        .clock(by_q$10$clock)
    );
    top$lanes$3$ctl$by_q$11 by_q$11(
        .d(by_q$11$d),
        .q(by_q$11$q),
        .clock(by_q$11$clock)
    );
    top$lanes$3$ctl$by_q$12 by_q$12(
        .d(by_q$12$d),
        .q(by_q$12$q),
        .clock(by_q$12$clock)
    );
    top$lanes$3$ctl$by_q$13 by_q$13(
        .d(by_q$13$d),
        .q(by_q$13$q),
        .clock(by_q$13$clock)
    );
    top$lanes$3$ctl$by_q$14 by_q$14(
        .d(by_q$14$d),
        .q(by_q$14$q),
        .clock(by_q$14$clock)
    );
    top$lanes$3$ctl$by_q$15 by_q$15(
        .d(by_q$15$d),
        .q(by_q$15$q),
        .clock(by_q$15$clock)
    );
    top$lanes$3$ctl$by_q$16 by_q$16(
        .d(by_q$16$d),
        .q(by_q$16$q),
        .clock(by_q$16$clock)
    );
    top$lanes$3$ctl$by_q$17 by_q$17(
        .d(by_q$17$d),
        .q(by_q$17$q),
        .clock(by_q$17$clock)
    );
    top$lanes$3$ctl$by_q$18 by_q$18(
        .d(by_q$18$d),
        .q(by_q$18$q),
        .clock(by_q$18$clock)
    );
    top$lanes$3$ctl$by_q$19 by_q$19(
        .d(by_q$19$d),
        .q(by_q$19$q),
        .clock(by_q$19$clock)
    );
    top$lanes$3$ctl$by_q$20 by_q$20(
        .d(by_q$20$d),
        .q(by_q$20$q),
        .clock(by_q$20$clock)
    );
    top$lanes$3$ctl$face_q$0 face_q$0(
        .d(face_q$0$d),
        .q(face_q$0$q),
        .clock(face_q$0$clock)
    );
    top$lanes$3$ctl$face_q$1 face_q$1(
        .d(face_q$1$d),
        .q(face_q$1$q),
        .clock(face_q$1$clock)
    );
    top$lanes$3$ctl$face_q$2 face_q$2(
        .d(face_q$2$d),
        .q(face_q$2$q),
        .clock(face_q$2$clock)
    );
    top$lanes$3$ctl$face_q$3 face_q$3(
        .d(face_q$3$d),
        .q(face_q$3$q),
        .clock(face_q$3$clock)
    );
    top$lanes$3$ctl$face_q$4 face_q$4(
        .d(face_q$4$d),
        .q(face_q$4$q),
        .clock(face_q$4$clock)
    );
    top$lanes$3$ctl$face_q$5 face_q$5(
        .d(face_q$5$d),
        .q(face_q$5$q),
        .clock(face_q$5$clock)
    );
    top$lanes$3$ctl$face_q$6 face_q$6(
        .d(face_q$6$d),
        .q(face_q$6$q),
        .clock(face_q$6$clock)
    );
    top$lanes$3$ctl$face_q$7 face_q$7(
        .d(face_q$7$d),
        .q(face_q$7$q),
        .clock(face_q$7$clock)
    );
    top$lanes$3$ctl$face_q$8 face_q$8(
        .d(face_q$8$d),
        .q(face_q$8$q),
        .clock(face_q$8$clock)
    );
    top$lanes$3$ctl$face_q$9 face_q$9(
        .d(face_q$9$d),
        .q(face_q$9$q),
        .clock(face_q$9$clock)
    );
    top$lanes$3$ctl$face_q$10 face_q$10(
        .d(face_q$10$d),
        .q(face_q$10$q),
        .clock(face_q$10$clock)
    );
    top$lanes$3$ctl$face_q$11 face_q$11(
        .d(face_q$11$d),
        .q(face_q$11$q),
        .clock(face_q$11$clock)
    );
    top$lanes$3$ctl$face_q$12 face_q$12(
        .d(face_q$12$d),
        .q(face_q$12$q),
        .clock(face_q$12$clock)
    );
    top$lanes$3$ctl$face_q$13 face_q$13(
        .d(face_q$13$d),
        .q(face_q$13$q),
        .clock(face_q$13$clock)
    );
    top$lanes$3$ctl$face_q$14 face_q$14(
        .d(face_q$14$d),
        .q(face_q$14$q),
        .clock(face_q$14$clock)
    );
    top$lanes$3$ctl$face_q$15 face_q$15(
        .d(face_q$15$d),
        .q(face_q$15$q),
        .clock(face_q$15$clock)
    );
    top$lanes$3$ctl$face_q$16 face_q$16(
        .d(face_q$16$d),
        .q(face_q$16$q),
        .clock(face_q$16$clock)
    );
    top$lanes$3$ctl$face_q$17 face_q$17(
        .d(face_q$17$d),
        .q(face_q$17$q),
        .clock(face_q$17$clock)
    );
    top$lanes$3$ctl$face_q$18 face_q$18(
        .d(face_q$18$d),
        .q(face_q$18$q),
        .clock(face_q$18$clock)
    );
    top$lanes$3$ctl$face_q$19 face_q$19(
        .d(face_q$19$d),
        .q(face_q$19$q),
        .clock(face_q$19$clock)
    );
    top$lanes$3$ctl$face_q$20 face_q$20(
        .d(face_q$20$d),
        .q(face_q$20$q),
        .clock(face_q$20$clock)
    );
    
    // Update code
    always @(*) begin
        nx_last$clock = clock;
        ny_last$clock = clock;
        nx_last$d = nx_last$q;
        ny_last$d = ny_last$q;
        x_q$0$clock = clock;
        dxm_q$0$clock = clock;
        dym_q$0$clock = clock;
        x_q$1$clock = clock;
        dxm_q$1$clock = clock;
        dym_q$1$clock = clock;
        x_q$2$clock = clock;
        dxm_q$2$clock = clock;
        dym_q$2$clock = clock;
        x_q$3$clock = clock;
        dxm_q$3$clock = clock;
        dym_q$3$clock = clock;
        x_q$4$clock = clock;
        dxm_q$4$clock = clock;
        dym_q$4$clock = clock;
        x_q$5$clock = clock;
        dxm_q$5$clock = clock;
        dym_q$5$clock = clock;
        x_q$6$clock = clock;
        dxm_q$6$clock = clock;
        dym_q$6$clock = clock;
        x_q$7$clock = clock;
        dxm_q$7$clock = clock;
        dym_q$7$clock = clock;
        x_q$8$clock = clock;
        dxm_q$8$clock = clock;
        dym_q$8$clock = clock;
        x_q$9$clock = clock;
        dxm_q$9$clock = clock;
        dym_q$9$clock = clock;
        v_q$0$clock = clock;
        er_q$0$clock = clock;
        pad_q$0$clock = clock;
        bx_q$0$clock = clock;
        by_q$0$clock = clock;
        face_q$0$clock = clock;
        v_q$1$clock = clock;
        er_q$1$clock = clock;
        pad_q$1$clock = clock;
        bx_q$1$clock = clock;
        by_q$1$clock = clock;
        face_q$1$clock = clock;
        v_q$2$clock = clock;
        er_q$2$clock = clock;
        pad_q$2$clock = clock;
        bx_q$2$clock = clock;
        by_q$2$clock = clock;
        face_q$2$clock = clock;
        v_q$3$clock = clock;
        er_q$3$clock = clock;
        pad_q$3$clock = clock;
        bx_q$3$clock = clock;
        by_q$3$clock = clock;
        face_q$3$clock = clock;
        v_q$4$clock = clock;
        er_q$4$clock = clock;
        pad_q$4$clock = clock;
        bx_q$4$clock = clock;
        by_q$4$clock = clock;
        face_q$4$clock = clock;
        v_q$5$clock = clock;
        er_q$5$clock = clock;
        pad_q$5$clock = clock;
        bx_q$5$clock = clock;
        by_q$5$clock = clock;
        face_q$5$clock = clock;
        v_q$6$clock = clock;
        er_q$6$clock = clock;
        pad_q$6$clock = clock;
        bx_q$6$clock = clock;
        by_q$6$clock = clock;
        face_q$6$clock = clock;
        v_q$7$clock = clock;
        er_q$7$clock = clock;
        pad_q$7$clock = clock;
        bx_q$7$clock = clock;
        by_q$7$clock = clock;
        face_q$7$clock = clock;
        v_q$8$clock = clock;
        er_q$8$clock = clock;
        pad_q$8$clock = clock;
        bx_q$8$clock = clock;
        by_q$8$clock = clock;
        face_q$8$clock = clock;
        v_q$9$clock = clock;
        er_q$9$clock = clock;
        pad_q$9$clock = clock;
        bx_q$9$clock = clock;
        by_q$9$clock = clock;
        face_q$9$clock = clock;
        v_q$10$clock = clock;
        er_q$10$clock = clock;
        pad_q$10$clock = clock;
        bx_q$10$clock = clock;
        by_q$10$clock = clock;
        face_q$10$clock = clock;
        v_q$11$clock = clock;
        er_q$11$clock = clock;
        pad_q$11$clock = clock;
        bx_q$11$clock = clock;
        by_q$11$clock = clock;
        face_q$11$clock = clock;
        v_q$12$clock = clock;
        er_q$12$clock = clock;
        pad_q$12$clock = clock;
        bx_q$12$clock = clock;
        by_q$12$clock = clock;
        face_q$12$clock = clock;
        v_q$13$clock = clock;
        er_q$13$clock = clock;
        pad_q$13$clock = clock;
        bx_q$13$clock = clock;
        by_q$13$clock = clock;
        face_q$13$clock = clock;
        v_q$14$clock = clock;
        er_q$14$clock = clock;
        pad_q$14$clock = clock;
        bx_q$14$clock = clock;
        by_q$14$clock = clock;
        face_q$14$clock = clock;
        v_q$15$clock = clock;
        er_q$15$clock = clock;
        pad_q$15$clock = clock;
        bx_q$15$clock = clock;
        by_q$15$clock = clock;
        face_q$15$clock = clock;
        v_q$16$clock = clock;
        er_q$16$clock = clock;
        pad_q$16$clock = clock;
        bx_q$16$clock = clock;
        by_q$16$clock = clock;
        face_q$16$clock = clock;
        v_q$17$clock = clock;
        er_q$17$clock = clock;
        pad_q$17$clock = clock;
        bx_q$17$clock = clock;
        by_q$17$clock = clock;
        face_q$17$clock = clock;
        v_q$18$clock = clock;
        er_q$18$clock = clock;
        pad_q$18$clock = clock;
        bx_q$18$clock = clock;
        by_q$18$clock = clock;
        face_q$18$clock = clock;
        v_q$19$clock = clock;
        er_q$19$clock = clock;
        pad_q$19$clock = clock;
        bx_q$19$clock = clock;
        by_q$19$clock = clock;
        face_q$19$clock = clock;
        v_q$20$clock = clock;
        er_q$20$clock = clock;
        pad_q$20$clock = clock;
        bx_q$20$clock = clock;
        by_q$20$clock = clock;
        face_q$20$clock = clock;
        x_q$0$d = x & coord_mask;
        y_q$0$d = y & coord_mask;
        sr_q$0$d = sr;
        dxn_q$0$d = dx_neg;
        dxm_q$0$d = dx_mag;
        dyn_q$0$d = dy_neg;
        dym_q$0$d = dy_mag;
        x_q$1$d = x_q$0$q;
        dxm_q$1$d = dxm_q$0$q;
        dym_q$1$d = dym_q$0$q;
        x_q$2$d = x_q$1$q;
        dxm_q$2$d = dxm_q$1$q;
        dym_q$2$d = dym_q$1$q;
        x_q$3$d = x_q$2$q;
        dxm_q$3$d = dxm_q$2$q;
        dym_q$3$d = dym_q$2$q;
        x_q$4$d = x_q$3$q;
        dxm_q$4$d = dxm_q$3$q;
        dym_q$4$d = dym_q$3$q;
        x_q$5$d = x_q$4$q;
        dxm_q$5$d = dxm_q$4$q;
        dym_q$5$d = dym_q$4$q;
        x_q$6$d = x_q$5$q;
        dxm_q$6$d = dxm_q$5$q;
        dym_q$6$d = dym_q$5$q;
        x_q$7$d = x_q$6$q;
        dxm_q$7$d = dxm_q$6$q;
        dym_q$7$d = dym_q$6$q;
        x_q$8$d = x_q$7$q;
        dxm_q$8$d = dxm_q$7$q;
        dym_q$8$d = dym_q$7$q;
        x_q$9$d = x_q$8$q;
        dxm_q$9$d = dxm_q$8$q;
        dym_q$9$d = dym_q$8$q;
        y_q$0$clock = clock;
        sr_q$0$clock = clock;
        dxn_q$0$clock = clock;
        dyn_q$0$clock = clock;
        y_q$1$clock = clock;
        sr_q$1$clock = clock;
        dxn_q$1$clock = clock;
        dyn_q$1$clock = clock;
        y_q$2$clock = clock;
        sr_q$2$clock = clock;
        dxn_q$2$clock = clock;
        dyn_q$2$clock = clock;
        y_q$3$clock = clock;
        sr_q$3$clock = clock;
        dxn_q$3$clock = clock;
        dyn_q$3$clock = clock;
        y_q$4$clock = clock;
        sr_q$4$clock = clock;
        dxn_q$4$clock = clock;
        dyn_q$4$clock = clock;
        y_q$5$clock = clock;
        sr_q$5$clock = clock;
        dxn_q$5$clock = clock;
        dyn_q$5$clock = clock;
        y_q$6$clock = clock;
        sr_q$6$clock = clock;
        dxn_q$6$clock = clock;
        dyn_q$6$clock = clock;
        y_q$7$clock = clock;
        sr_q$7$clock = clock;
        dxn_q$7$clock = clock;
        dyn_q$7$clock = clock;
        y_q$8$clock = clock;
        sr_q$8$clock = clock;
        dxn_q$8$clock = clock;
        dyn_q$8$clock = clock;
        y_q$1$d = y_q$0$q;
        sr_q$1$d = sr_q$0$q;
        dxn_q$1$d = dxn_q$0$q;
        dyn_q$1$d = dyn_q$0$q;
        y_q$2$d = y_q$1$q;
        sr_q$2$d = sr_q$1$q;
        dxn_q$2$d = dxn_q$1$q;
        dyn_q$2$d = dyn_q$1$q;
        y_q$3$d = y_q$2$q;
        sr_q$3$d = sr_q$2$q;
        dxn_q$3$d = dxn_q$2$q;
        dyn_q$3$d = dyn_q$2$q;
        y_q$4$d = y_q$3$q;
        sr_q$4$d = sr_q$3$q;
        dxn_q$4$d = dxn_q$3$q;
        dyn_q$4$d = dyn_q$3$q;
        y_q$5$d = y_q$4$q;
        sr_q$5$d = sr_q$4$q;
        dxn_q$5$d = dxn_q$4$q;
        dyn_q$5$d = dyn_q$4$q;
        y_q$6$d = y_q$5$q;
        sr_q$6$d = sr_q$5$q;
        dxn_q$6$d = dxn_q$5$q;
        dyn_q$6$d = dyn_q$5$q;
        y_q$7$d = y_q$6$q;
        sr_q$7$d = sr_q$6$q;
        dxn_q$7$d = dxn_q$6$q;
        dyn_q$7$d = dyn_q$6$q;
        y_q$8$d = y_q$7$q;
        sr_q$8$d = sr_q$7$q;
        dxn_q$8$d = dxn_q$7$q;
        dyn_q$8$d = dyn_q$7$q;
        x_t = x_q$9$q;
        dx_mag_t = dxm_q$9$q;
        dy_mag_t = dym_q$9$q;
        nx_last$d = dims[('h0)+:(16)] - 'h1;
        ny_last$d = dims[('h10)+:(16)] - 'h1;
        x_out = 1'b0;
        if (dxm_q$8$q != 'h0) begin
            if (dxn_q$8$q) begin
                x_out = x_q$8$q == nx_last$q;
            end
            else begin
                x_out = x_q$8$q == 'h0;
            end
        end
        y_out = 1'b0;
        if (dym_q$8$q != 'h0) begin
            if (dyn_q$8$q) begin
                y_out = y_q$8$q == ny_last$q;
            end
            else begin
                y_out = y_q$8$q == 'h0;
            end
        end
        dx_nz = dxm_q$8$q != 'h0;
        dy_nz = dym_q$8$q != 'h0;
        sel = 7'(sr_q$8$q) | (7'(dxn_q$8$q) << 'h1) | (7'(dx_nz) << 'h2) | (7'(dyn_q$8$q) << 'h3) | (7'(dy_nz) << 'h4) | (7'(x_out) << 'h5) | (7'(y_out) << 'h6);
        sel_q$0$clock = clock;
        sel_q$0$d = sel;
        sel_t$0 = sel_q$0$q;
        sel_q$1$clock = clock;
        sel_q$1$d = sel;
        sel_t$1 = sel_q$1$q;
        sel_q$2$clock = clock;
        sel_q$2$d = sel;
        sel_t$2 = sel_q$2$q;
        sel_q$3$clock = clock;
        sel_q$3$d = sel;
        sel_t$3 = sel_q$3$q;
        v_q$0$d = valid;
        er_q$0$d = er;
        pad_q$0$d = pad;
        bx_q$0$d = base_x & coord_mask;
        by_q$0$d = base_y & coord_mask;
        face_q$0$d = face;
        v_q$1$d = v_q$0$q;
        er_q$1$d = er_q$0$q;
        pad_q$1$d = pad_q$0$q;
        bx_q$1$d = bx_q$0$q;
        by_q$1$d = by_q$0$q;
        face_q$1$d = face_q$0$q;
        v_q$2$d = v_q$1$q;
        er_q$2$d = er_q$1$q;
        pad_q$2$d = pad_q$1$q;
        bx_q$2$d = bx_q$1$q;
        by_q$2$d = by_q$1$q;
        face_q$2$d = face_q$1$q;
        v_q$3$d = v_q$2$q;
        er_q$3$d = er_q$2$q;
        pad_q$3$d = pad_q$2$q;
        bx_q$3$d = bx_q$2$q;
        by_q$3$d = by_q$2$q;
        face_q$3$d = face_q$2$q;
        v_q$4$d = v_q$3$q;
        er_q$4$d = er_q$3$q;
        pad_q$4$d = pad_q$3$q;
        bx_q$4$d = bx_q$3$q;
        by_q$4$d = by_q$3$q;
        face_q$4$d = face_q$3$q;
        v_q$5$d = v_q$4$q;
        er_q$5$d = er_q$4$q;
        pad_q$5$d = pad_q$4$q;
        bx_q$5$d = bx_q$4$q;
        by_q$5$d = by_q$4$q;
        face_q$5$d = face_q$4$q;
        v_q$6$d = v_q$5$q;
        er_q$6$d = er_q$5$q;
        pad_q$6$d = pad_q$5$q;
        bx_q$6$d = bx_q$5$q;
        by_q$6$d = by_q$5$q;
        face_q$6$d = face_q$5$q;
        v_q$7$d = v_q$6$q;
        er_q$7$d = er_q$6$q;
        pad_q$7$d = pad_q$6$q;
        bx_q$7$d = bx_q$6$q;
        by_q$7$d = by_q$6$q;
        face_q$7$d = face_q$6$q;
        v_q$8$d = v_q$7$q;
        er_q$8$d = er_q$7$q;
        pad_q$8$d = pad_q$7$q;
        bx_q$8$d = bx_q$7$q;
        by_q$8$d = by_q$7$q;
        face_q$8$d = face_q$7$q;
        v_q$9$d = v_q$8$q;
        er_q$9$d = er_q$8$q;
        pad_q$9$d = pad_q$8$q;
        bx_q$9$d = bx_q$8$q;
        by_q$9$d = by_q$8$q;
        face_q$9$d = face_q$8$q;
        v_q$10$d = v_q$9$q;
        er_q$10$d = er_q$9$q;
        pad_q$10$d = pad_q$9$q;
        bx_q$10$d = bx_q$9$q;
        by_q$10$d = by_q$9$q;
        face_q$10$d = face_q$9$q;
        v_q$11$d = v_q$10$q;
        er_q$11$d = er_q$10$q;
        pad_q$11$d = pad_q$10$q;
        bx_q$11$d = bx_q$10$q;
        by_q$11$d = by_q$10$q;
        face_q$11$d = face_q$10$q;
        v_q$12$d = v_q$11$q;
        er_q$12$d = er_q$11$q;
        pad_q$12$d = pad_q$11$q;
        bx_q$12$d = bx_q$11$q;
        by_q$12$d = by_q$11$q;
        face_q$12$d = face_q$11$q;
        v_q$13$d = v_q$12$q;
        er_q$13$d = er_q$12$q;
        pad_q$13$d = pad_q$12$q;
        bx_q$13$d = bx_q$12$q;
        by_q$13$d = by_q$12$q;
        face_q$13$d = face_q$12$q;
        v_q$14$d = v_q$13$q;
        er_q$14$d = er_q$13$q;
        pad_q$14$d = pad_q$13$q;
        bx_q$14$d = bx_q$13$q;
        by_q$14$d = by_q$13$q;
        face_q$14$d = face_q$13$q;
        v_q$15$d = v_q$14$q;
        er_q$15$d = er_q$14$q;
        pad_q$15$d = pad_q$14$q;
        bx_q$15$d = bx_q$14$q;
        by_q$15$d = by_q$14$q;
        face_q$15$d = face_q$14$q;
        v_q$16$d = v_q$15$q;
        er_q$16$d = er_q$15$q;
        pad_q$16$d = pad_q$15$q;
        bx_q$16$d = bx_q$15$q;
        by_q$16$d = by_q$15$q;
        face_q$16$d = face_q$15$q;
        v_q$17$d = v_q$16$q;
        er_q$17$d = er_q$16$q;
        pad_q$17$d = pad_q$16$q;
        bx_q$17$d = bx_q$16$q;
        by_q$17$d = by_q$16$q;
        face_q$17$d = face_q$16$q;
        v_q$18$d = v_q$17$q;
        er_q$18$d = er_q$17$q;
        pad_q$18$d = pad_q$17$q;
        bx_q$18$d = bx_q$17$q;
        by_q$18$d = by_q$17$q;
        face_q$18$d = face_q$17$q;
        v_q$19$d = v_q$18$q;
        er_q$19$d = er_q$18$q;
        pad_q$19$d = pad_q$18$q;
        bx_q$19$d = bx_q$18$q;
        by_q$19$d = by_q$18$q;
        face_q$19$d = face_q$18$q;
        v_q$20$d = v_q$19$q;
        er_q$20$d = er_q$19$q;
        pad_q$20$d = pad_q$19$q;
        bx_q$20$d = bx_q$19$q;
        by_q$20$d = by_q$19$q;
        face_q$20$d = face_q$19$q;
        res_beat = v_q$20$q;
        res_valid = v_q$20$q & ~pad_q$20$q;
        px_valid = v_q$20$q & er_q$20$q & ~pad_q$20$q;
        px_x = bx_q$20$q;
        px_y = by_q$20$q;
        px_face = face_q$20$q;
    end
    
endmodule // top$lanes$3$ctl
module top$lanes$3$ctl$bx_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$0
module top$lanes$3$ctl$bx_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$1
module top$lanes$3$ctl$bx_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$10
module top$lanes$3$ctl$bx_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$11
module top$lanes$3$ctl$bx_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$12
module top$lanes$3$ctl$bx_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$13
module top$lanes$3$ctl$bx_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$14
module top$lanes$3$ctl$bx_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$15
module top$lanes$3$ctl$bx_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$16
module top$lanes$3$ctl$bx_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$17
module top$lanes$3$ctl$bx_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$18
module top$lanes$3$ctl$bx_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$19
module top$lanes$3$ctl$bx_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$2
module top$lanes$3$ctl$bx_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$20
module top$lanes$3$ctl$bx_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$3
module top$lanes$3$ctl$bx_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$4
module top$lanes$3$ctl$bx_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$5
module top$lanes$3$ctl$bx_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$6
module top$lanes$3$ctl$bx_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$7
module top$lanes$3$ctl$bx_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$8
module top$lanes$3$ctl$bx_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$bx_q$9
module top$lanes$3$ctl$by_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$0
module top$lanes$3$ctl$by_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$1
module top$lanes$3$ctl$by_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$10
module top$lanes$3$ctl$by_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$11
module top$lanes$3$ctl$by_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$12
module top$lanes$3$ctl$by_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$13
module top$lanes$3$ctl$by_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$14
module top$lanes$3$ctl$by_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$15
module top$lanes$3$ctl$by_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$16
module top$lanes$3$ctl$by_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$17
module top$lanes$3$ctl$by_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$18
module top$lanes$3$ctl$by_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$19
module top$lanes$3$ctl$by_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$2
module top$lanes$3$ctl$by_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$20
module top$lanes$3$ctl$by_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$3
module top$lanes$3$ctl$by_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$4
module top$lanes$3$ctl$by_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$5
module top$lanes$3$ctl$by_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$6
module top$lanes$3$ctl$by_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$7
module top$lanes$3$ctl$by_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$8
module top$lanes$3$ctl$by_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$by_q$9
module top$lanes$3$ctl$dxm_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxm_q$0
module top$lanes$3$ctl$dxm_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxm_q$1
module top$lanes$3$ctl$dxm_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxm_q$2
module top$lanes$3$ctl$dxm_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxm_q$3
module top$lanes$3$ctl$dxm_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxm_q$4
module top$lanes$3$ctl$dxm_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxm_q$5
module top$lanes$3$ctl$dxm_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxm_q$6
module top$lanes$3$ctl$dxm_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxm_q$7
module top$lanes$3$ctl$dxm_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxm_q$8
module top$lanes$3$ctl$dxm_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxm_q$9
module top$lanes$3$ctl$dxn_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxn_q$0
module top$lanes$3$ctl$dxn_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxn_q$1
module top$lanes$3$ctl$dxn_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxn_q$2
module top$lanes$3$ctl$dxn_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxn_q$3
module top$lanes$3$ctl$dxn_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxn_q$4
module top$lanes$3$ctl$dxn_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxn_q$5
module top$lanes$3$ctl$dxn_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxn_q$6
module top$lanes$3$ctl$dxn_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxn_q$7
module top$lanes$3$ctl$dxn_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dxn_q$8
module top$lanes$3$ctl$dym_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dym_q$0
module top$lanes$3$ctl$dym_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dym_q$1
module top$lanes$3$ctl$dym_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dym_q$2
module top$lanes$3$ctl$dym_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dym_q$3
module top$lanes$3$ctl$dym_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dym_q$4
module top$lanes$3$ctl$dym_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dym_q$5
module top$lanes$3$ctl$dym_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dym_q$6
module top$lanes$3$ctl$dym_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dym_q$7
module top$lanes$3$ctl$dym_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dym_q$8
module top$lanes$3$ctl$dym_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dym_q$9
module top$lanes$3$ctl$dyn_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dyn_q$0
module top$lanes$3$ctl$dyn_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dyn_q$1
module top$lanes$3$ctl$dyn_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dyn_q$2
module top$lanes$3$ctl$dyn_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dyn_q$3
module top$lanes$3$ctl$dyn_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dyn_q$4
module top$lanes$3$ctl$dyn_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dyn_q$5
module top$lanes$3$ctl$dyn_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dyn_q$6
module top$lanes$3$ctl$dyn_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dyn_q$7
module top$lanes$3$ctl$dyn_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$dyn_q$8
module top$lanes$3$ctl$er_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$0
module top$lanes$3$ctl$er_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$1
module top$lanes$3$ctl$er_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$10
module top$lanes$3$ctl$er_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$11
module top$lanes$3$ctl$er_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$12
module top$lanes$3$ctl$er_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$13
module top$lanes$3$ctl$er_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$14
module top$lanes$3$ctl$er_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$15
module top$lanes$3$ctl$er_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$16
module top$lanes$3$ctl$er_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$17
module top$lanes$3$ctl$er_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$18
module top$lanes$3$ctl$er_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$19
module top$lanes$3$ctl$er_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$2
module top$lanes$3$ctl$er_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$20
module top$lanes$3$ctl$er_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$3
module top$lanes$3$ctl$er_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$4
module top$lanes$3$ctl$er_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$5
module top$lanes$3$ctl$er_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$6
module top$lanes$3$ctl$er_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$7
module top$lanes$3$ctl$er_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$8
module top$lanes$3$ctl$er_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$er_q$9
module top$lanes$3$ctl$face_q$0(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$0
module top$lanes$3$ctl$face_q$1(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$1
module top$lanes$3$ctl$face_q$10(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$10
module top$lanes$3$ctl$face_q$11(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$11
module top$lanes$3$ctl$face_q$12(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$12
module top$lanes$3$ctl$face_q$13(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$13
module top$lanes$3$ctl$face_q$14(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$14
module top$lanes$3$ctl$face_q$15(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$15
module top$lanes$3$ctl$face_q$16(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$16
module top$lanes$3$ctl$face_q$17(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$17
module top$lanes$3$ctl$face_q$18(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$18
module top$lanes$3$ctl$face_q$19(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$19
module top$lanes$3$ctl$face_q$2(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$2
module top$lanes$3$ctl$face_q$20(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$20
module top$lanes$3$ctl$face_q$3(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$3
module top$lanes$3$ctl$face_q$4(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$4
module top$lanes$3$ctl$face_q$5(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$5
module top$lanes$3$ctl$face_q$6(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$6
module top$lanes$3$ctl$face_q$7(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$7
module top$lanes$3$ctl$face_q$8(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$8
module top$lanes$3$ctl$face_q$9(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 3'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$ctl$face_q$9
module top$lanes$3$ctl$nx_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$ctl$nx_last
module top$lanes$3$ctl$ny_last(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$ctl$ny_last
module top$lanes$3$ctl$pad_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$0
module top$lanes$3$ctl$pad_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$1
module top$lanes$3$ctl$pad_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$10
module top$lanes$3$ctl$pad_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$11
module top$lanes$3$ctl$pad_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$12
module top$lanes$3$ctl$pad_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$13
module top$lanes$3$ctl$pad_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$14
module top$lanes$3$ctl$pad_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$15
module top$lanes$3$ctl$pad_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$16
module top$lanes$3$ctl$pad_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$17
module top$lanes$3$ctl$pad_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$18
module top$lanes$3$ctl$pad_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$19
module top$lanes$3$ctl$pad_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$2
module top$lanes$3$ctl$pad_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$20
module top$lanes$3$ctl$pad_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$3
module top$lanes$3$ctl$pad_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$4
module top$lanes$3$ctl$pad_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$5
module top$lanes$3$ctl$pad_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$6
module top$lanes$3$ctl$pad_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$7
module top$lanes$3$ctl$pad_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$8
module top$lanes$3$ctl$pad_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$pad_q$9
module top$lanes$3$ctl$sel_q$0(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$ctl$sel_q$0
module top$lanes$3$ctl$sel_q$1(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$ctl$sel_q$1
module top$lanes$3$ctl$sel_q$2(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$ctl$sel_q$2
module top$lanes$3$ctl$sel_q$3(d,q,clock);
    
    // Module arguments
    input wire  [6:0] d;
    output reg  [6:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 7'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$3$ctl$sel_q$3
module top$lanes$3$ctl$sr_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$sr_q$0
module top$lanes$3$ctl$sr_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$sr_q$1
module top$lanes$3$ctl$sr_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$sr_q$2
module top$lanes$3$ctl$sr_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$sr_q$3
module top$lanes$3$ctl$sr_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$sr_q$4
module top$lanes$3$ctl$sr_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$sr_q$5
module top$lanes$3$ctl$sr_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$sr_q$6
module top$lanes$3$ctl$sr_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$sr_q$7
module top$lanes$3$ctl$sr_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$sr_q$8
module top$lanes$3$ctl$v_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$0
module top$lanes$3$ctl$v_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$1
module top$lanes$3$ctl$v_q$10(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$10
module top$lanes$3$ctl$v_q$11(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$11
module top$lanes$3$ctl$v_q$12(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$12
module top$lanes$3$ctl$v_q$13(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$13
module top$lanes$3$ctl$v_q$14(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$14
module top$lanes$3$ctl$v_q$15(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$15
module top$lanes$3$ctl$v_q$16(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$16
module top$lanes$3$ctl$v_q$17(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$17
module top$lanes$3$ctl$v_q$18(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$18
module top$lanes$3$ctl$v_q$19(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$19
module top$lanes$3$ctl$v_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$2
module top$lanes$3$ctl$v_q$20(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$20
module top$lanes$3$ctl$v_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$3
module top$lanes$3$ctl$v_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$4
module top$lanes$3$ctl$v_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$5
module top$lanes$3$ctl$v_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$6
module top$lanes$3$ctl$v_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$7
module top$lanes$3$ctl$v_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$8
module top$lanes$3$ctl$v_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$v_q$9
module top$lanes$3$ctl$x_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$x_q$0
module top$lanes$3$ctl$x_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$x_q$1
module top$lanes$3$ctl$x_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$x_q$2
module top$lanes$3$ctl$x_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$x_q$3
module top$lanes$3$ctl$x_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$x_q$4
module top$lanes$3$ctl$x_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$x_q$5
module top$lanes$3$ctl$x_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$x_q$6
module top$lanes$3$ctl$x_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$x_q$7
module top$lanes$3$ctl$x_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$x_q$8
module top$lanes$3$ctl$x_q$9(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$x_q$9
module top$lanes$3$ctl$y_q$0(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$y_q$0
module top$lanes$3$ctl$y_q$1(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$y_q$1
module top$lanes$3$ctl$y_q$2(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$y_q$2
module top$lanes$3$ctl$y_q$3(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$y_q$3
module top$lanes$3$ctl$y_q$4(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$y_q$4
module top$lanes$3$ctl$y_q$5(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$y_q$5
module top$lanes$3$ctl$y_q$6(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$y_q$6
module top$lanes$3$ctl$y_q$7(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$y_q$7
module top$lanes$3$ctl$y_q$8(d,q,clock);
    
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
          
endmodule // top$lanes$3$ctl$y_q$8
module top$lanes$3$feed(clock,beats,beat_valid,value,x,y,pad,invalid,halo,sr,er,base_x,base_y,face,at_edge,dx_neg,dx_mag,dy_neg,dy_mag,g_from_left_xm,g_from_left_ym,g_from_left_zm,g_from_right_xp,g_from_right_yp,g_from_right_zp,g_to_right_xm,g_to_right_ym,g_to_right_zm,g_to_left_xp,g_to_left_yp,g_to_left_zp,o_valid,o_value,o_x,o_y,o_pad,o_invalid,o_sr,o_er,o_edge,o_face,o_base_x,o_base_y,o_dx_neg,o_dx_mag,o_dy_neg,o_dy_mag,gx_neg,gx_mag,gy_neg,gy_mag,gz_neg,gz_mag);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  beat_valid;
    input wire  [15:0] value;
    input wire  [15:0] x;
    input wire  [15:0] y;
    input wire  pad;
    input wire  invalid;
    input wire  halo;
    input wire  sr;
    input wire  er;
    input wire  [15:0] base_x;
    input wire  [15:0] base_y;
    input wire  [2:0] face;
    input wire  at_edge;
    input wire  dx_neg;
    input wire  [15:0] dx_mag;
    input wire  dy_neg;
    input wire  [15:0] dy_mag;
    input wire  [15:0] g_from_left_xm;
    input wire  [15:0] g_from_left_ym;
    input wire  [15:0] g_from_left_zm;
    input wire  [15:0] g_from_right_xp;
    input wire  [15:0] g_from_right_yp;
    input wire  [15:0] g_from_right_zp;
    output reg  [15:0] g_to_right_xm;
    output reg  [15:0] g_to_right_ym;
    output reg  [15:0] g_to_right_zm;
    output reg  [15:0] g_to_left_xp;
    output reg  [15:0] g_to_left_yp;
    output reg  [15:0] g_to_left_zp;
    output reg  o_valid;
    output reg  [15:0] o_value;
    output reg  [15:0] o_x;
    output reg  [15:0] o_y;
    output reg  o_pad;
    output reg  o_invalid;
    output reg  o_sr;
    output reg  o_er;
    output reg  o_edge;
    output reg  [2:0] o_face;
    output reg  [15:0] o_base_x;
    output reg  [15:0] o_base_y;
    output reg  o_dx_neg;
    output reg  [15:0] o_dx_mag;
    output reg  o_dy_neg;
    output reg  [15:0] o_dy_mag;
    output reg  gx_neg;
    output reg  [15:0] gx_mag;
    output reg  gy_neg;
    output reg  [15:0] gy_mag;
    output reg  gz_neg;
    output reg  [15:0] gz_mag;
    
    // Constant declarations
    localparam  use_gradient = 1'b0;
    
    // Stub signals
    reg  abc$clock;
    reg  [63:0] abc$beats;
    reg  [15:0] abc$value;
    reg  [15:0] abc$x;
    reg  [15:0] abc$from_left_xm;
    reg  [15:0] abc$from_left_ym;
    reg  [15:0] abc$from_left_zm;
    reg  [15:0] abc$from_right_xp;
    reg  [15:0] abc$from_right_yp;
    reg  [15:0] abc$from_right_zp;
    wire  [15:0] abc$to_right_xm = 'h0;
    wire  [15:0] abc$to_right_ym = 'h0;
    wire  [15:0] abc$to_right_zm = 'h0;
    wire  [15:0] abc$to_left_xp = 'h0;
    wire  [15:0] abc$to_left_yp = 'h0;
    wire  [15:0] abc$to_left_zp = 'h0;
    wire  [15:0] abc$o_value = 'h0;
    wire  abc$gx_neg = 'h0;
    wire  [15:0] abc$gx_mag = 'h0;
    wire  abc$gy_neg = 'h0;
    wire  [15:0] abc$gy_mag = 'h0;
    wire  abc$gz_neg = 'h0;
    wire  [15:0] abc$gz_mag = 'h0;
    
    // Sub module instances
    
    // Update code
    reg  [15:0] o_value_pass;
    always @(*) begin
        abc$clock = clock;
        abc$beats = beats;
        abc$value = value;
        abc$x = x;
        abc$from_left_xm = g_from_left_xm;
        abc$from_left_ym = g_from_left_ym;
        abc$from_left_zm = g_from_left_zm;
        abc$from_right_xp = g_from_right_xp;
        abc$from_right_yp = g_from_right_yp;
        abc$from_right_zp = g_from_right_zp;
        g_to_right_xm = abc$to_right_xm;
        g_to_right_ym = abc$to_right_ym;
        g_to_right_zm = abc$to_right_zm;
        g_to_left_xp = abc$to_left_xp;
        g_to_left_yp = abc$to_left_yp;
        g_to_left_zp = abc$to_left_zp;
        gx_neg = abc$gx_neg;
        gx_mag = abc$gx_mag;
        gy_neg = abc$gy_neg;
        gy_mag = abc$gy_mag;
        gz_neg = abc$gz_neg;
        gz_mag = abc$gz_mag;
        if (use_gradient) begin
            o_value_pass = abc$o_value;
        end
        else begin
            o_value_pass = value;
        end
        o_valid = beat_valid & ~halo;
        o_x = x;
        o_y = y;
        o_pad = pad;
        o_invalid = invalid;
        o_sr = sr;
        o_er = er;
        o_edge = at_edge;
        o_face = face;
        o_base_x = base_x;
        o_base_y = base_y;
        o_dx_neg = dx_neg;
        o_dx_mag = dx_mag;
        o_dy_neg = dy_neg;
        o_dy_mag = dy_mag;
        o_value = o_value_pass;
    end
    
endmodule // top$lanes$3$feed
module top$late_go(d,q,clock);
    
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
          
endmodule // top$late_go
module top$late_wait(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$late_wait
module top$view(clock,host_write,host_address,host_data,q$0,q$1,q$2,q$3,q$4,q$5,q$6,q$7,q$8,q$9,q$10);
    
    // Module arguments
    input wire  clock;
    input wire  host_write;
    input wire  [23:0] host_address;
    input wire  [63:0] host_data;
    output reg  [63:0] q$0;
    output reg  [63:0] q$1;
    output reg  [63:0] q$2;
    output reg  [63:0] q$3;
    output reg  [63:0] q$4;
    output reg  [63:0] q$5;
    output reg  [63:0] q$6;
    output reg  [63:0] q$7;
    output reg  [63:0] q$8;
    output reg  [63:0] q$9;
    output reg  [63:0] q$10;
    
    // Constant declarations
    localparam  address$0 = 24'h20;
    localparam  address$1 = 24'h21;
    localparam  address$2 = 24'h22;
    localparam  address$3 = 24'h23;
    localparam  address$4 = 24'h24;
    localparam  address$5 = 24'h25;
    localparam  address$6 = 24'h26;
    localparam  address$7 = 24'h27;
    localparam  address$8 = 24'h28;
    localparam  address$9 = 24'h29;
    localparam  address$10 = 24'h2a;
    
    // Stub signals
    reg  [63:0] r$0$d;
    wire  [63:0] r$0$q;
    reg  r$0$clock;
    reg  [63:0] r$1$d;
    wire  [63:0] r$1$q;
    reg  r$1$clock;
    reg  [63:0] r$2$d;
    wire  [63:0] r$2$q;
    reg  r$2$clock;
    reg  [63:0] r$3$d;
    wire  [63:0] r$3$q;
    reg  r$3$clock;
    reg  [63:0] r$4$d;
    wire  [63:0] r$4$q;
    reg  r$4$clock;
    reg  [63:0] r$5$d;
    wire  [63:0] r$5$q;
    reg  r$5$clock;
    reg  [63:0] r$6$d;
    wire  [63:0] r$6$q;
    reg  r$6$clock;
    reg  [63:0] r$7$d;
    wire  [63:0] r$7$q;
    reg  r$7$clock;
    reg  [63:0] r$8$d;
    wire  [63:0] r$8$q;
    reg  r$8$clock;
    reg  [63:0] r$9$d;
    wire  [63:0] r$9$q;
    reg  r$9$clock;
    reg  [63:0] r$10$d;
    wire  [63:0] r$10$q;
    reg  r$10$clock;
    
    // Sub module instances
    top$view$r$0 r$0(
        .d(r$0$d),
        .q(r$0$q),
        .clock(r$0$clock)
    );
    top$view$r$1 r$1(
        .d(r$1$d),
        .q(r$1$q),
        .clock(r$1$clock)
    );
    top$view$r$2 r$2(
        .d(r$2$d),
        .q(r$2$q),
        .clock(r$2$clock)
    );
    top$view$r$3 r$3(
        .d(r$3$d),
        .q(r$3$q),
        .clock(r$3$clock)
    );
    top$view$r$4 r$4(
        .d(r$4$d),
        .q(r$4$q),
        .clock(r$4$clock)
    );
    top$view$r$5 r$5(
        .d(r$5$d),
        .q(r$5$q),
        .clock(r$5$clock)
    );
    top$view$r$6 r$6(
        .d(r$6$d),
        .q(r$6$q),
        .clock(r$6$clock)
    );
    top$view$r$7 r$7(
        .d(r$7$d),
        .q(r$7$q),
        .clock(r$7$clock)
    );
    top$view$r$8 r$8(
        .d(r$8$d),
        .q(r$8$q),
        .clock(r$8$clock)
    );
    top$view$r$9 r$9(
        .d(r$9$d),
        .q(r$9$q),
        .clock(r$9$clock)
    );
    top$view$r$10 r$10(
        .d(r$10$d),
        .q(r$10$q),
        .clock(r$10$clock)
    );
    
    // Update code
    always @(*) begin
        r$0$clock = clock;
        r$0$d = r$0$q;
        if (host_write & (host_address == address$0)) begin
            r$0$d = host_data;
        end
        q$0 = r$0$q;
        r$1$clock = clock;
        r$1$d = r$1$q;
        if (host_write & (host_address == address$1)) begin
            r$1$d = host_data;
        end
        q$1 = r$1$q;
        r$2$clock = clock;
        r$2$d = r$2$q;
        if (host_write & (host_address == address$2)) begin
            r$2$d = host_data;
        end
        q$2 = r$2$q;
        r$3$clock = clock;
        r$3$d = r$3$q;
        if (host_write & (host_address == address$3)) begin
            r$3$d = host_data;
        end
        q$3 = r$3$q;
        r$4$clock = clock;
        r$4$d = r$4$q;
        if (host_write & (host_address == address$4)) begin
            r$4$d = host_data;
        end
        q$4 = r$4$q;
        r$5$clock = clock;
        r$5$d = r$5$q;
        if (host_write & (host_address == address$5)) begin
            r$5$d = host_data;
        end
        q$5 = r$5$q;
        r$6$clock = clock;
        r$6$d = r$6$q;
        if (host_write & (host_address == address$6)) begin
            r$6$d = host_data;
        end
        q$6 = r$6$q;
        r$7$clock = clock;
        r$7$d = r$7$q;
        if (host_write & (host_address == address$7)) begin
            r$7$d = host_data;
        end
        q$7 = r$7$q;
        r$8$clock = clock;
        r$8$d = r$8$q;
        if (host_write & (host_address == address$8)) begin
            r$8$d = host_data;
        end
        q$8 = r$8$q;
        r$9$clock = clock;
        r$9$d = r$9$q;
        if (host_write & (host_address == address$9)) begin
            r$9$d = host_data;
        end
        q$9 = r$9$q;
        r$10$clock = clock;
        r$10$d = r$10$q;
        if (host_write & (host_address == address$10)) begin
            r$10$d = host_data;
        end
        q$10 = r$10$q;
    end
    
endmodule // top$view
module top$view$r$0(d,q,clock);
    
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
          
endmodule // top$view$r$0
module top$view$r$1(d,q,clock);
    
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
          
endmodule // top$view$r$1
module top$view$r$10(d,q,clock);
    
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
          
endmodule // top$view$r$10
module top$view$r$2(d,q,clock);
    
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
          
endmodule // top$view$r$2
module top$view$r$3(d,q,clock);
    
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
          
endmodule // top$view$r$3
module top$view$r$4(d,q,clock);
    
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
          
endmodule // top$view$r$4
module top$view$r$5(d,q,clock);
    
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
          
endmodule // top$view$r$5
module top$view$r$6(d,q,clock);
    
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
          
endmodule // top$view$r$6
module top$view$r$7(d,q,clock);
    
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
          
endmodule // top$view$r$7
module top$view$r$8(d,q,clock);
    
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
          
endmodule // top$view$r$8
module top$view$r$9(d,q,clock);
    
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
          
endmodule // top$view$r$9
