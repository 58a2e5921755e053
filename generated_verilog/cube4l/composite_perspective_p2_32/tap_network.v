module top$lanes$0$taps(clock,beats,x,res,res_beat,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,a$0,a$1,a$2,a$3,a$4,a$5,a$6,a$7,a$8);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  [15:0] x;
    input wire  [63:0] res;
    input wire  res_beat;
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
    output reg  [63:0] a$0;
    output reg  [63:0] a$1;
    output reg  [63:0] a$2;
    output reg  [63:0] a$3;
    output reg  [63:0] a$4;
    output reg  [63:0] a$5;
    output reg  [63:0] a$6;
    output reg  [63:0] a$7;
    output reg  [63:0] a$8;
    
    // Constant declarations
    localparam  left8 = 1'b0;
    localparam  p_mask = 16'h1;
    
    // Stub signals
    reg  rows$clock;
    reg  [63:0] rows$beats;
    reg  [63:0] rows$res;
    reg  rows$res_beat;
    wire  [63:0] rows$tap$0;
    wire  [63:0] rows$tap$1;
    wire  [63:0] rows$tap$2;
    wire  [63:0] rows$tap$3;
    wire  [63:0] rows$tap$4;
    wire  [63:0] rows$tap$5;
    wire  [63:0] rows$tap$6;
    wire  [63:0] rows$tap$7;
    wire  [63:0] rows$tap$8;
    reg  t0$clock;
    reg  [63:0] t0$read;
    reg  t0$use_prev;
    reg  [63:0] t0$link_in$0;
    wire  [63:0] t0$pass$0;
    wire  [63:0] t0$a;
    reg  t1$clock;
    reg  [63:0] t1$read;
    reg  t1$use_prev;
    reg  [63:0] t1$link_in$0;
    reg  [63:0] t1$link_in$1;
    wire  [63:0] t1$pass$0;
    wire  [63:0] t1$pass$1;
    wire  [63:0] t1$a;
    reg  t2$clock;
    reg  [63:0] t2$read;
    reg  t2$use_prev;
    wire  [63:0] t2$a;
    reg  t3$clock;
    reg  [63:0] t3$read;
    reg  t3$use_prev;
    reg  [63:0] t3$link_in$0;
    reg  [63:0] t3$link_in$1;
    wire  [63:0] t3$pass$0;
    wire  [63:0] t3$pass$1;
    wire  [63:0] t3$a;
    reg  t4$clock;
    reg  [63:0] t4$read;
    reg  t4$use_prev;
    wire  [63:0] t4$a;
    reg  t5$clock;
    reg  [63:0] t5$read;
    reg  t5$use_prev;
    reg  [63:0] t5$link_in$0;
    reg  [63:0] t5$link_in$1;
    reg  [63:0] t5$link_in$2;
    wire  [63:0] t5$pass$0;
    wire  [63:0] t5$pass$1;
    wire  [63:0] t5$pass$2;
    wire  [63:0] t5$a;
    reg  t6$clock;
    reg  [63:0] t6$read;
    reg  t6$use_prev;
    reg  [63:0] t6$link_in$0;
    wire  [63:0] t6$pass$0;
    wire  [63:0] t6$a;
    reg  t7$clock;
    reg  [63:0] t7$read;
    reg  t7$use_prev;
    reg  [63:0] t7$link_in$0;
    wire  [63:0] t7$pass$0;
    wire  [63:0] t7$a;
    reg  t8$clock;
    reg  [63:0] t8$read;
    reg  t8$use_prev;
    reg  [63:0] t8$link_in$0;
    wire  [63:0] t8$pass$0;
    wire  [63:0] t8$a;
    
    // Local signals
    reg  first;
    reg  last;
    
    // Sub module instances
    top$lanes$0$taps$rows rows(
        .clock(rows$clock),
        .beats(rows$beats),
        .res(rows$res),
        .res_beat(rows$res_beat),
        .tap$0(rows$tap$0),
        .tap$1(rows$tap$1),
        .tap$2(rows$tap$2),
        .tap$3(rows$tap$3),
        .tap$4(rows$tap$4),
        .tap$5(rows$tap$5),
        .tap$6(rows$tap$6),
        .tap$7(rows$tap$7),
        .tap$8(rows$tap$8)
    );
    top$lanes$0$taps$t0 t0(
        .clock(t0$clock),
        .read(t0$read),
        .use_prev(t0$use_prev),
        .link_in$0(t0$link_in$0),
        .pass$0(t0$pass$0),
        .a(t0$a)
    );
    top$lanes$0$taps$t1 t1(
        .clock(t1$clock),
        .read(t1$read),
        .use_prev(t1$use_prev),
        .link_in$0(t1$link_in$0),
        .link_in$1(t1$link_in$1),
        .pass$0(t1$pass$0),
        .pass$1(t1$pass$1),
        .a(t1$a)
    );
    top$lanes$0$taps$t2 t2(
        .clock(t2$clock),
        .read(t2$read),
        .use_prev(t2$use_prev),
        .a(t2$a)
    );
    top$lanes$0$taps$t3 t3(
        .clock(t3$clock),
        .read(t3$read),
        .use_prev(t3$use_prev),
        .link_in$0(t3$link_in$0),
        .link_in$1(t3$link_in$1),
        .pass$0(t3$pass$0),
        .pass$1(t3$pass$1),
        .a(t3$a)
    );
    top$lanes$0$taps$t4 t4(
        .clock(t4$clock),
        .read(t4$read),
        .use_prev(t4$use_prev),
        .a(t4$a)
    );
    top$lanes$0$taps$t5 t5(
        .clock(t5$clock),
        .read(t5$read),
        .use_prev(t5$use_prev),
        .link_in$0(t5$link_in$0),
        .link_in$1(t5$link_in$1),
        .link_in$2(t5$link_in$2),
        .pass$0(t5$pass$0),
        .pass$1(t5$pass$1),
        .pass$2(t5$pass$2),
        .a(t5$a)
    );
    top$lanes$0$taps$t6 t6(
        .clock(t6$clock),
        .read(t6$read),
        .use_prev(t6$use_prev),
        .link_in$0(t6$link_in$0),
        .pass$0(t6$pass$0),
        .a(t6$a)
    );
    top$lanes$0$taps$t7 t7(
        .clock(t7$clock),
        .read(t7$read),
        .use_prev(t7$use_prev),
        .link_in$0(t7$link_in$0),
        .pass$0(t7$pass$0),
        .a(t7$a)
    );
    top$lanes$0$taps$t8 t8(
        .clock(t8$clock),
        .read(t8$read),
        .use_prev(t8$use_prev),
        .link_in$0(t8$link_in$0),
        .pass$0(t8$pass$0),
        .a(t8$a)
    );
    
    // Update code
    always @(*) begin
        rows$clock = clock;
        rows$beats = beats;
        rows$res = res;
        rows$res_beat = res_beat;
        first = (x & p_mask) == 'h0;
        last = (x & p_mask) == p_mask;
        t0$clock = clock;
        t0$read = rows$tap$0;
        t0$use_prev = 1'b0;
        t0$link_in$0 = t0i1;
        t0s0 = t0$pass$0;
        a$0 = t0$a;
        t1$clock = clock;
        t1$read = rows$tap$1;
        t1$use_prev = first;
        t1$link_in$0 = t1i1;
        t1$link_in$1 = t1i2;
        t1s0 = t1$pass$0;
        t1s1 = t1$pass$1;
        a$1 = t1$a;
        t2$clock = clock;
        t2$read = rows$tap$2;
        t2$use_prev = ~last;
        a$2 = t2$a;
        t3$clock = clock;
        t3$read = rows$tap$3;
        t3$use_prev = 1'b0;
        t3$link_in$0 = t3i1;
        t3$link_in$1 = t3i2;
        t3s0 = t3$pass$0;
        t3s1 = t3$pass$1;
        a$3 = t3$a;
        t4$clock = clock;
        t4$read = rows$tap$4;
        t4$use_prev = 1'b0;
        a$4 = t4$a;
        t5$clock = clock;
        t5$read = rows$tap$5;
        t5$use_prev = first;
        t5$link_in$0 = t5i1;
        t5$link_in$1 = t5i2;
        t5$link_in$2 = t5i3;
        t5s0 = t5$pass$0;
        t5s1 = t5$pass$1;
        t5s2 = t5$pass$2;
        a$5 = t5$a;
        t6$clock = clock;
        t6$read = rows$tap$6;
        t6$use_prev = ~last;
        t6$link_in$0 = t6i1;
        t6s0 = t6$pass$0;
        a$6 = t6$a;
        t7$clock = clock;
        t7$read = rows$tap$7;
        t7$use_prev = first;
        t7$link_in$0 = t7i1;
        t7s0 = t7$pass$0;
        a$7 = t7$a;
        t8$clock = clock;
        t8$read = rows$tap$8;
        t8$use_prev = ~last;
        if (left8) begin
            t8$link_in$0 = t8il;
        end
        else begin
            t8$link_in$0 = t8i1;
        end
        t8s0 = t8$pass$0;
        a$8 = t8$a;
    end
    
endmodule // top$lanes$0$taps
module top$lanes$0$taps$rows(clock,beats,res,res_beat,tap$0,tap$1,tap$2,tap$3,tap$4,tap$5,tap$6,tap$7,tap$8);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  [63:0] res;
    input wire  res_beat;
    output reg  [63:0] tap$0;
    output reg  [63:0] tap$1;
    output reg  [63:0] tap$2;
    output reg  [63:0] tap$3;
    output reg  [63:0] tap$4;
    output reg  [63:0] tap$5;
    output reg  [63:0] tap$6;
    output reg  [63:0] tap$7;
    output reg  [63:0] tap$8;
    
    // Constant declarations
    localparam  pick$0 = 15'b100000000;
    localparam  pick$1 = 15'b1000000000;
    localparam  pick$2 = 15'b100000000;
    localparam  pick$3 = 15'b100000000000000;
    localparam  pick$4 = 15'b10000;
    localparam  pick$5 = 15'b10000000000000;
    localparam  pick$6 = 15'b1000000000000;
    localparam  pick$7 = 15'b1000;
    localparam  pick$8 = 15'b100;
    localparam  ring_less = 16'h10;
    
    // Stub signals
    reg  ring$clock;
    reg  [63:0] ring$data_in;
    reg  ring$write_enable;
    wire  [63:0] ring$data_out;
    reg  [15:0] ring$last;
    reg  beam0$clock;
    reg  [63:0] beam0$data_in;
    reg  beam0$write_enable;
    wire  [63:0] beam0$data_out;
    reg  [15:0] beam0$last;
    reg  beam1$clock;
    reg  [63:0] beam1$data_in;
    reg  beam1$write_enable;
    wire  [63:0] beam1$data_out;
    reg  [15:0] beam1$last;
    reg  [63:0] stage$0$d;
    wire  [63:0] stage$0$q;
    reg  stage$0$clock;
    reg  [63:0] stage$1$d;
    wire  [63:0] stage$1$q;
    reg  stage$1$clock;
    reg  [63:0] stage$2$d;
    wire  [63:0] stage$2$q;
    reg  stage$2$clock;
    reg  [63:0] stage$3$d;
    wire  [63:0] stage$3$q;
    reg  stage$3$clock;
    reg  [63:0] stage$4$d;
    wire  [63:0] stage$4$q;
    reg  stage$4$clock;
    reg  [63:0] stage$5$d;
    wire  [63:0] stage$5$q;
    reg  stage$5$clock;
    reg  [63:0] stage$6$d;
    wire  [63:0] stage$6$q;
    reg  stage$6$clock;
    reg  [63:0] stage$7$d;
    wire  [63:0] stage$7$q;
    reg  stage$7$clock;
    reg  [63:0] stage$8$d;
    wire  [63:0] stage$8$q;
    reg  stage$8$clock;
    reg  [63:0] stage$9$d;
    wire  [63:0] stage$9$q;
    reg  stage$9$clock;
    reg  [63:0] stage$10$d;
    wire  [63:0] stage$10$q;
    reg  stage$10$clock;
    reg  [63:0] stage$11$d;
    wire  [63:0] stage$11$q;
    reg  stage$11$clock;
    reg  [15:0] slice$d;
    wire  [15:0] slice$q;
    reg  slice$clock;
    reg  [15:0] beam$d;
    wire  [15:0] beam$q;
    reg  beam$clock;
    reg  [15:0] slice_less_beam$d;
    wire  [15:0] slice_less_beam$q;
    reg  slice_less_beam$clock;
    reg  [15:0] ring_last$d;
    wire  [15:0] ring_last$q;
    reg  ring_last$clock;
    reg  [15:0] beam_last$d;
    wire  [15:0] beam_last$q;
    reg  beam_last$clock;
    
    // Local signals
    reg  [63:0] cand$0;
    reg  [63:0] cand$1;
    reg  [63:0] cand$2;
    reg  [63:0] cand$3;
    reg  [63:0] cand$4;
    reg  [63:0] cand$5;
    reg  [63:0] cand$6;
    reg  [63:0] cand$7;
    reg  [63:0] cand$8;
    reg  [63:0] cand$9;
    reg  [63:0] cand$10;
    reg  [63:0] cand$11;
    reg  [63:0] cand$12;
    reg  [63:0] cand$13;
    reg  [63:0] cand$14;
    reg  [63:0] sel$0;
    reg  [63:0] sel$1;
    reg  [63:0] sel$2;
    reg  [63:0] sel$3;
    reg  [63:0] sel$4;
    reg  [63:0] sel$5;
    reg  [63:0] sel$6;
    reg  [63:0] sel$7;
    reg  [63:0] sel$8;
    
    // Sub module instances
    top$lanes$0$taps$rows$ring ring(
        .clock(ring$clock),
        .data_in(ring$data_in),
        .write_enable(ring$write_enable),
        .data_out(ring$data_out),
        .last(ring$last)
    );
    top$lanes$0$taps$rows$beam0 beam0(
        .clock(beam0$clock),
        .data_in(beam0$data_in),
        .write_enable(beam0$write_enable),
        .data_out(beam0$data_out),
        .last(beam0$last)
    );
    top$lanes$0$taps$rows$beam1 beam1(
        .clock(beam1$clock),
        .data_in(beam1$data_in),
        .write_enable(beam1$write_enable),
        .data_out(beam1$data_out),
        .last(beam1$last)
    );
    top$lanes$0$taps$rows$stage$0 stage$0(
        .d(stage$0$d),
        .q(stage$0$q),
        .clock(stage$0$clock)
    );
    top$lanes$0$taps$rows$stage$1 stage$1(
        .d(stage$1$d),
        .q(stage$1$q),
        .clock(stage$1$clock)
    );
    top$lanes$0$taps$rows$stage$2 stage$2(
        .d(stage$2$d),
        .q(stage$2$q),
        .clock(stage$2$clock)
    );
    top$lanes$0$taps$rows$stage$3 stage$3(
        .d(stage$3$d),
        .q(stage$3$q),
        .clock(stage$3$clock)
    );
    top$lanes$0$taps$rows$stage$4 stage$4(
        .d(stage$4$d),
        .q(stage$4$q),
        .clock(stage$4$clock)
    );
    top$lanes$0$taps$rows$stage$5 stage$5(
        .d(stage$5$d),
        .q(stage$5$q),
        .clock(stage$5$clock)
    );
    top$lanes$0$taps$rows$stage$6 stage$6(
        .d(stage$6$d),
        .q(stage$6$q),
        .clock(stage$6$clock)
    );
    top$lanes$0$taps$rows$stage$7 stage$7(
        .d(stage$7$d),
        .q(stage$7$q),
        .clock(stage$7$clock)
    );
    top$lanes$0$taps$rows$stage$8 stage$8(
        .d(stage$8$d),
        .q(stage$8$q),
        .clock(stage$8$clock)
    );
    top$lanes$0$taps$rows$stage$9 stage$9(
        .d(stage$9$d),
        .q(stage$9$q),
        .clock(stage$9$clock)
    );
    top$lanes$0$taps$rows$stage$10 stage$10(
        .d(stage$10$d),
        .q(stage$10$q),
        .clock(stage$10$clock)
    );
    top$lanes$0$taps$rows$stage$11 stage$11(
        .d(stage$11$d),
        .q(stage$11$q),
        .clock(stage$11$clock)
    );
    top$lanes$0$taps$rows$slice slice(
        .d(slice$d),
        .q(slice$q),
        .clock(slice$clock)
    );
    top$lanes$0$taps$rows$beam beam(
        .d(beam$d),
        .q(beam$q),
        .clock(beam$clock)
    );
    top$lanes$0$taps$rows$slice_less_beam slice_less_beam(
        .d(slice_less_beam$d),
        .q(slice_less_beam$q),
        .clock(slice_less_beam$clock)
    );
    top$lanes$0$taps$rows$ring_last ring_last(
        .d(ring_last$d),
        .q(ring_last$q),
        .clock(ring_last$clock)
    );
    top$lanes$0$taps$rows$beam_last beam_last(
        .d(beam_last$d),
        .q(beam_last$q),
        .clock(beam_last$clock)
    );
    
    // Update code
    always @(*) begin
        slice$clock = clock;
        beam$clock = clock;
        slice_less_beam$clock = clock;
        ring_last$clock = clock;
        beam_last$clock = clock;
        slice$d = slice$q;
        beam$d = beam$q;
        slice_less_beam$d = slice_less_beam$q;
        ring_last$d = ring_last$q;
        beam_last$d = beam_last$q;
        slice$d = beats[('h0)+:(16)];
        beam$d = beats[('h20)+:(16)];
        slice_less_beam$d = slice$q - beam$q;
        ring_last$d = slice_less_beam$q - ring_less;
        beam_last$d = beam$q - 'h1;
        ring$last = ring_last$q;
        beam0$last = beam_last$q;
        beam1$last = beam_last$q;
        ring$clock = clock;
        beam0$clock = clock;
        beam1$clock = clock;
        stage$0$clock = clock;
        stage$1$clock = clock;
        stage$2$clock = clock;
        stage$3$clock = clock;
        stage$4$clock = clock;
        stage$5$clock = clock;
        stage$6$clock = clock;
        stage$7$clock = clock;
        stage$8$clock = clock;
        stage$9$clock = clock;
        stage$10$clock = clock;
        stage$11$clock = clock;
        ring$data_in = res;
        ring$write_enable = res_beat;
        beam0$data_in = ring$data_out;
        beam0$write_enable = 1'b1;
        beam1$data_in = beam0$data_out;
        beam1$write_enable = 1'b1;
        cand$0 = ring$data_out;
        cand$5 = beam0$data_out;
        cand$10 = beam1$data_out;
        stage$0$d = cand$0;
        stage$1$d = stage$0$q;
        stage$2$d = stage$1$q;
        stage$3$d = stage$2$q;
        cand$1 = stage$0$q;
        cand$2 = stage$1$q;
        cand$3 = stage$2$q;
        cand$4 = stage$3$q;
        stage$4$d = cand$5;
        stage$5$d = stage$4$q;
        stage$6$d = stage$5$q;
        stage$7$d = stage$6$q;
        cand$6 = stage$4$q;
        cand$7 = stage$5$q;
        cand$8 = stage$6$q;
        cand$9 = stage$7$q;
        stage$8$d = cand$10;
        stage$9$d = stage$8$q;
        stage$10$d = stage$9$q;
        stage$11$d = stage$10$q;
        cand$11 = stage$8$q;
        cand$12 = stage$9$q;
        cand$13 = stage$10$q;
        cand$14 = stage$11$q;
        sel$0 = cand$0;
        if (pick$0[1]) begin
            sel$0 = cand$1;
        end
        if (pick$0[2]) begin
            sel$0 = cand$2;
        end
        if (pick$0[3]) begin
            sel$0 = cand$3;
        end
        if (pick$0[4]) begin
            sel$0 = cand$4;
        end
        if (pick$0[5]) begin
            sel$0 = cand$5;
        end
        if (pick$0[6]) begin
            sel$0 = cand$6;
        end
        if (pick$0[7]) begin
            sel$0 = cand$7;
        end
        if (pick$0[8]) begin
            sel$0 = cand$8;
        end
        if (pick$0[9]) begin
            sel$0 = cand$9;
        end
        if (pick$0[10]) begin
            sel$0 = cand$10;
        end
        if (pick$0[11]) begin
            sel$0 = cand$11;
        end
        if (pick$0[12]) begin
            sel$0 = cand$12;
        end
        if (pick$0[13]) begin
            sel$0 = cand$13;
        end
        if (pick$0[14]) begin
            sel$0 = cand$14;
        end
        tap$0 = sel$0;
        sel$1 = cand$0;
        if (pick$1[1]) begin
            sel$1 = cand$1;
        end
        if (pick$1[2]) begin
            sel$1 = cand$2;
        end
        if (pick$1[3]) begin
            sel$1 = cand$3;
        end
        if (pick$1[4]) begin
            sel$1 = cand$4;
        end
        if (pick$1[5]) begin
            sel$1 = cand$5;
        end
        if (pick$1[6]) begin
            sel$1 = cand$6;
        end
        if (pick$1[7]) begin
            sel$1 = cand$7;
        end
        if (pick$1[8]) begin
            sel$1 = cand$8;
        end
        if (pick$1[9]) begin
            sel$1 = cand$9;
        end
        if (pick$1[10]) begin
            sel$1 = cand$10;
        end
        if (pick$1[11]) begin
            sel$1 = cand$11;
        end
        if (pick$1[12]) begin
            sel$1 = cand$12;
        end
        if (pick$1[13]) begin
            sel$1 = cand$13;
        end
        if (pick$1[14]) begin
            sel$1 = cand$14;
        end
        tap$1 = sel$1;
        sel$2 = cand$0;
        if (pick$2[1]) begin
            sel$2 = cand$1;
        end
        if (pick$2[2]) begin
            sel$2 = cand$2;
        end
        if (pick$2[3]) begin
            sel$2 = cand$3;
        end
        if (pick$2[4]) begin
            sel$2 = cand$4;
        end
        if (pick$2[5]) begin
            sel$2 = cand$5;
        end
        if (pick$2[6]) begin
            sel$2 = cand$6;
        end
        if (pick$2[7]) begin
            sel$2 = cand$7;
        end
        if (pick$2[8]) begin
            sel$2 = cand$8;
        end
        if (pick$2[9]) begin
            sel$2 = cand$9;
        end
        if (pick$2[10]) begin
            sel$2 = cand$10;
        end
        if (pick$2[11]) begin
            sel$2 = cand$11;
        end
        if (pick$2[12]) begin
            sel$2 = cand$12;
        end
        if (pick$2[13]) begin
            sel$2 = cand$13;
        end
        if (pick$2[14]) begin
            sel$2 = cand$14;
        end
        tap$2 = sel$2;
        sel$3 = cand$0;
        if (pick$3[1]) begin
            sel$3 = cand$1;
        end
        if (pick$3[2]) begin
            sel$3 = cand$2;
        end
        if (pick$3[3]) begin
            sel$3 = cand$3;
        end
        if (pick$3[4]) begin
            sel$3 = cand$4;
        end
        if (pick$3[5]) begin
            sel$3 = cand$5;
        end
        if (pick$3[6]) begin
            sel$3 = cand$6;
        end
        if (pick$3[7]) begin
            sel$3 = cand$7;
        end
        if (pick$3[8]) begin
            sel$3 = cand$8;
        end
        if (pick$3[9]) begin
            sel$3 = cand$9;
        end
        if (pick$3[10]) begin
            sel$3 = cand$10;
        end
        if (pick$3[11]) begin
            sel$3 = cand$11;
        end
        if (pick$3[12]) begin
            sel$3 = cand$12;
        end
        if (pick$3[13]) begin
            sel$3 = cand$13;
        end
        if (pick$3[14]) begin
            sel$3 = cand$14;
        end
        tap$3 = sel$3;
        sel$4 = cand$0;
        if (pick$4[1]) begin
            sel$4 = cand$1;
        end
        if (pick$4[2]) begin
            sel$4 = cand$2;
        end
        if (pick$4[3]) begin
            sel$4 = cand$3;
        end
        if (pick$4[4]) begin
            sel$4 = cand$4;
        end
        if (pick$4[5]) begin
            sel$4 = cand$5;
        end
        if (pick$4[6]) begin
            sel$4 = cand$6;
        end
        if (pick$4[7]) begin
            sel$4 = cand$7;
        end
        if (pick$4[8]) begin
            sel$4 = cand$8;
        end
        if (pick$4[9]) begin
            sel$4 = cand$9;
        end
        if (pick$4[10]) begin
            sel$4 = cand$10;
        end
        if (pick$4[11]) begin
            sel$4 = cand$11;
        end
        if (pick$4[12]) begin
            sel$4 = cand$12;
        end
        if (pick$4[13]) begin
            sel$4 = cand$13;
        end
        if (pick$4[14]) begin
            sel$4 = cand$14;
        end
        tap$4 = sel$4;
        sel$5 = cand$0;
        if (pick$5[1]) begin
            sel$5 = cand$1;
        end
        if (pick$5[2]) begin
            sel$5 = cand$2;
        end
        if (pick$5[3]) begin
            sel$5 = cand$3;
        end
        if (pick$5[4]) begin
            sel$5 = cand$4;
        end
        if (pick$5[5]) begin
            sel$5 = cand$5;
        end
        if (pick$5[6]) begin
            sel$5 = cand$6;
        end
        if (pick$5[7]) begin
            sel$5 = cand$7;
        end
        if (pick$5[8]) begin
            sel$5 = cand$8;
        end
        if (pick$5[9]) begin
            sel$5 = cand$9;
        end
        if (pick$5[10]) begin
            sel$5 = cand$10;
        end
        if (pick$5[11]) begin
            sel$5 = cand$11;
        end
        if (pick$5[12]) begin
            sel$5 = cand$12;
        end
        if (pick$5[13]) begin
            sel$5 = cand$13;
        end
        if (pick$5[14]) begin
            sel$5 = cand$14;
        end
        tap$5 = sel$5;
        sel$6 = cand$0;
        if (pick$6[1]) begin
            sel$6 = cand$1;
        end
        if (pick$6[2]) begin
            sel$6 = cand$2;
        end
        if (pick$6[3]) begin
            sel$6 = cand$3;
        end
        if (pick$6[4]) begin
            sel$6 = cand$4;
        end
        if (pick$6[5]) begin
            sel$6 = cand$5;
        end
        if (pick$6[6]) begin
            sel$6 = cand$6;
        end
        if (pick$6[7]) begin
            sel$6 = cand$7;
        end
        if (pick$6[8]) begin
            sel$6 = cand$8;
        end
        if (pick$6[9]) begin
            sel$6 = cand$9;
        end
        if (pick$6[10]) begin
            sel$6 = cand$10;
        end
        if (pick$6[11]) begin
            sel$6 = cand$11;
        end
        if (pick$6[12]) begin
            sel$6 = cand$12;
        end
        if (pick$6[13]) begin
            sel$6 = cand$13;
        end
        if (pick$6[14]) begin
            sel$6 = cand$14;
        end
        tap$6 = sel$6;
        sel$7 = cand$0;
        if (pick$7[1]) begin
            sel$7 = cand$1;
        end
        if (pick$7[2]) begin
            sel$7 = cand$2;
        end
        if (pick$7[3]) begin
            sel$7 = cand$3;
        end
        if (pick$7[4]) begin
            sel$7 = cand$4;
        end
        if (pick$7[5]) begin
            sel$7 = cand$5;
        end
        if (pick$7[6]) begin
            sel$7 = cand$6;
        end
        if (pick$7[7]) begin
            sel$7 = cand$7;
        end
        if (pick$7[8]) begin
            sel$7 = cand$8;
        end
        if (pick$7[9]) begin
            sel$7 = cand$9;
        end
        if (pick$7[10]) begin
            sel$7 = cand$10;
        end
        if (pick$7[11]) begin
            sel$7 = cand$11;
        end
        if (pick$7[12]) begin
            sel$7 = cand$12;
        end
        if (pick$7[13]) begin
            sel$7 = cand$13;
        end
        if (pick$7[14]) begin
            sel$7 = cand$14;
        end
        tap$7 = sel$7;
        sel$8 = cand$0;
        if (pick$8[1]) begin
            sel$8 = cand$1;
        end
        if (pick$8[2]) begin
            sel$8 = cand$2;
        end
        if (pick$8[3]) begin
            sel$8 = cand$3;
        end
        if (pick$8[4]) begin
            sel$8 = cand$4;
        end
        if (pick$8[5]) begin
            sel$8 = cand$5;
        end
        if (pick$8[6]) begin
            sel$8 = cand$6;
        end
        if (pick$8[7]) begin
            sel$8 = cand$7;
        end
        if (pick$8[8]) begin
            sel$8 = cand$8;
        end
        if (pick$8[9]) begin
            sel$8 = cand$9;
        end
        if (pick$8[10]) begin
            sel$8 = cand$10;
        end
        if (pick$8[11]) begin
            sel$8 = cand$11;
        end
        if (pick$8[12]) begin
            sel$8 = cand$12;
        end
        if (pick$8[13]) begin
            sel$8 = cand$13;
        end
        if (pick$8[14]) begin
            sel$8 = cand$14;
        end
        tap$8 = sel$8;
    end
    
endmodule // top$lanes$0$taps$rows
module top$lanes$0$taps$rows$beam(d,q,clock);
    
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
endmodule // top$lanes$0$taps$rows$beam
module top$lanes$0$taps$rows$beam0(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'hd;
    localparam  has_ring = 1'b1;
    localparam  mask = 64'hff00ff00ff00ff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [63:0] one$d;
    wire  [63:0] one$q;
    reg  one$clock;
    reg  [63:0] two$d;
    wire  [63:0] two$q;
    reg  two$clock;
    reg  [63:0] short$d;
    wire  [63:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$0$taps$rows$beam0$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$0$taps$rows$beam0$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$0$taps$rows$beam0$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$0$taps$rows$beam0$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$0$taps$rows$beam0$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$0$taps$rows$beam0$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$0$taps$rows$beam0$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$0$taps$rows$beam0$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$0$taps$rows$beam0$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$0$taps$rows$beam0$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$0$taps$rows$beam0$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [63:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$0$taps$rows$beam0
module top$lanes$0$taps$rows$beam0$bound(d,q,clock);
    
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
endmodule // top$lanes$0$taps$rows$beam0$bound
module top$lanes$0$taps$rows$beam0$head(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$rows$beam0$head
module top$lanes$0$taps$rows$beam0$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$taps$rows$beam0$is_one
module top$lanes$0$taps$rows$beam0$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$taps$rows$beam0$is_short
module top$lanes$0$taps$rows$beam0$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$taps$rows$beam0$is_two
module top$lanes$0$taps$rows$beam0$one(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$beam0$one
module top$lanes$0$taps$rows$beam0$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$rows$beam0$ptr
module top$lanes$0$taps$rows$beam0$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [31:0] stored_word = {write_data[55:48], write_data[39:32], write_data[23:16], write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [31:0] mem_0_0[13:0];
    reg [31:0] rd_0;
    reg [31:0] q_0;
    reg [31:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[31:0] <= mem_0_0[read_address[3:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[3:0]] <= stored_word[31:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[31:24], 8'd0, r_0[23:16], 8'd0, r_0[15:8], 8'd0, r_0[7:0]};
    end
endmodule // top$lanes$0$taps$rows$beam0$ram
module top$lanes$0$taps$rows$beam0$rd(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$rows$beam0$rd
module top$lanes$0$taps$rows$beam0$short(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$beam0$short
module top$lanes$0$taps$rows$beam0$two(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$beam0$two
module top$lanes$0$taps$rows$beam1(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'hd;
    localparam  has_ring = 1'b1;
    localparam  mask = 64'hff00ff00ff00ff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [63:0] one$d;
    wire  [63:0] one$q;
    reg  one$clock;
    reg  [63:0] two$d;
    wire  [63:0] two$q;
    reg  two$clock;
    reg  [63:0] short$d;
    wire  [63:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$0$taps$rows$beam1$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$0$taps$rows$beam1$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$0$taps$rows$beam1$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$0$taps$rows$beam1$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$0$taps$rows$beam1$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$0$taps$rows$beam1$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$0$taps$rows$beam1$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$0$taps$rows$beam1$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$0$taps$rows$beam1$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$0$taps$rows$beam1$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$0$taps$rows$beam1$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [63:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$0$taps$rows$beam1
module top$lanes$0$taps$rows$beam1$bound(d,q,clock);
    
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
endmodule // top$lanes$0$taps$rows$beam1$bound
module top$lanes$0$taps$rows$beam1$head(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$rows$beam1$head
module top$lanes$0$taps$rows$beam1$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$taps$rows$beam1$is_one
module top$lanes$0$taps$rows$beam1$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$taps$rows$beam1$is_short
module top$lanes$0$taps$rows$beam1$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$taps$rows$beam1$is_two
module top$lanes$0$taps$rows$beam1$one(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$beam1$one
module top$lanes$0$taps$rows$beam1$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$rows$beam1$ptr
module top$lanes$0$taps$rows$beam1$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [31:0] stored_word = {write_data[55:48], write_data[39:32], write_data[23:16], write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [31:0] mem_0_0[13:0];
    reg [31:0] rd_0;
    reg [31:0] q_0;
    reg [31:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[31:0] <= mem_0_0[read_address[3:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[3:0]] <= stored_word[31:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[31:24], 8'd0, r_0[23:16], 8'd0, r_0[15:8], 8'd0, r_0[7:0]};
    end
endmodule // top$lanes$0$taps$rows$beam1$ram
module top$lanes$0$taps$rows$beam1$rd(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$rows$beam1$rd
module top$lanes$0$taps$rows$beam1$short(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$beam1$short
module top$lanes$0$taps$rows$beam1$two(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$beam1$two
module top$lanes$0$taps$rows$beam_last(d,q,clock);
    
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
endmodule // top$lanes$0$taps$rows$beam_last
module top$lanes$0$taps$rows$ring(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h1de;
    localparam  has_ring = 1'b1;
    localparam  mask = 64'hff00ff00ff00ff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [63:0] one$d;
    wire  [63:0] one$q;
    reg  one$clock;
    reg  [63:0] two$d;
    wire  [63:0] two$q;
    reg  two$clock;
    reg  [63:0] short$d;
    wire  [63:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$0$taps$rows$ring$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$0$taps$rows$ring$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$0$taps$rows$ring$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$0$taps$rows$ring$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$0$taps$rows$ring$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$0$taps$rows$ring$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$0$taps$rows$ring$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$0$taps$rows$ring$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$0$taps$rows$ring$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$0$taps$rows$ring$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$0$taps$rows$ring$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [63:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$0$taps$rows$ring
module top$lanes$0$taps$rows$ring$bound(d,q,clock);
    
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
endmodule // top$lanes$0$taps$rows$ring$bound
module top$lanes$0$taps$rows$ring$head(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$rows$ring$head
module top$lanes$0$taps$rows$ring$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$taps$rows$ring$is_one
module top$lanes$0$taps$rows$ring$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$taps$rows$ring$is_short
module top$lanes$0$taps$rows$ring$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$0$taps$rows$ring$is_two
module top$lanes$0$taps$rows$ring$one(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$ring$one
module top$lanes$0$taps$rows$ring$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$rows$ring$ptr
module top$lanes$0$taps$rows$ring$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [31:0] stored_word = {write_data[55:48], write_data[39:32], write_data[23:16], write_data[7:0]};
    (* no_rw_check *)
    reg [31:0] mem_0_0[478:0];
    reg [31:0] rd_0;
    reg [31:0] q_0;
    reg [31:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[31:0] <= mem_0_0[read_address[8:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[8:0]] <= stored_word[31:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[31:24], 8'd0, r_0[23:16], 8'd0, r_0[15:8], 8'd0, r_0[7:0]};
    end
endmodule // top$lanes$0$taps$rows$ring$ram
module top$lanes$0$taps$rows$ring$rd(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$taps$rows$ring$rd
module top$lanes$0$taps$rows$ring$short(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$ring$short
module top$lanes$0$taps$rows$ring$two(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$ring$two
module top$lanes$0$taps$rows$ring_last(d,q,clock);
    
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
endmodule // top$lanes$0$taps$rows$ring_last
module top$lanes$0$taps$rows$slice(d,q,clock);
    
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
endmodule // top$lanes$0$taps$rows$slice
module top$lanes$0$taps$rows$slice_less_beam(d,q,clock);
    
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
endmodule // top$lanes$0$taps$rows$slice_less_beam
module top$lanes$0$taps$rows$stage$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$0
module top$lanes$0$taps$rows$stage$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$1
module top$lanes$0$taps$rows$stage$10(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$10
module top$lanes$0$taps$rows$stage$11(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$11
module top$lanes$0$taps$rows$stage$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$2
module top$lanes$0$taps$rows$stage$3(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$3
module top$lanes$0$taps$rows$stage$4(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$4
module top$lanes$0$taps$rows$stage$5(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$5
module top$lanes$0$taps$rows$stage$6(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$6
module top$lanes$0$taps$rows$stage$7(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$7
module top$lanes$0$taps$rows$stage$8(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$8
module top$lanes$0$taps$rows$stage$9(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$rows$stage$9
module top$lanes$0$taps$t0(clock,read,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t0$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t0$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = read;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$0$taps$t0
module top$lanes$0$taps$t0$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t0$links$0
module top$lanes$0$taps$t0$prev(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t0$prev
module top$lanes$0$taps$t1(clock,read,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b0;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t1$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t1$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$0$taps$t1$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = read;
        pass$1 = links$0$q;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$0$taps$t1
module top$lanes$0$taps$t1$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t1$links$0
module top$lanes$0$taps$t1$links$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t1$links$1
module top$lanes$0$taps$t1$prev(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t1$prev
module top$lanes$0$taps$t2(clock,read,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Stub signals
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t2$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        stream = read;
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$0$taps$t2
module top$lanes$0$taps$t2$prev(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t2$prev
module top$lanes$0$taps$t3(clock,read,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b0;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t3$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t3$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$0$taps$t3$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = read;
        pass$1 = links$0$q;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$0$taps$t3
module top$lanes$0$taps$t3$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t3$links$0
module top$lanes$0$taps$t3$links$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t3$links$1
module top$lanes$0$taps$t3$prev(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t3$prev
module top$lanes$0$taps$t4(clock,read,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Stub signals
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t4$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        stream = read;
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$0$taps$t4
module top$lanes$0$taps$t4$prev(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t4$prev
module top$lanes$0$taps$t5(clock,read,use_prev,link_in$0,link_in$1,link_in$2,pass$0,pass$1,pass$2,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    input wire  [63:0] link_in$2;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] pass$2;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b1;
    localparam  take$1 = 1'b0;
    localparam  take$2 = 1'b0;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] links$2$d;
    wire  [63:0] links$2$q;
    reg  links$2$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t5$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t5$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$0$taps$t5$links$2 links$2(
        .d(links$2$d),
        .q(links$2$q),
        .clock(links$2$clock)
    );
    top$lanes$0$taps$t5$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        links$2$clock = clock;
        links$2$d = link_in$2;
        pass$0 = read;
        pass$1 = links$0$q;
        pass$2 = links$1$q;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        if (take$2) begin
            stream = links$2$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$0$taps$t5
module top$lanes$0$taps$t5$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t5$links$0
module top$lanes$0$taps$t5$links$1(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t5$links$1
module top$lanes$0$taps$t5$links$2(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t5$links$2
module top$lanes$0$taps$t5$prev(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t5$prev
module top$lanes$0$taps$t6(clock,read,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t6$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t6$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = read;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$0$taps$t6
module top$lanes$0$taps$t6$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t6$links$0
module top$lanes$0$taps$t6$prev(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t6$prev
module top$lanes$0$taps$t7(clock,read,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t7$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t7$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = read;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$0$taps$t7
module top$lanes$0$taps$t7$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t7$links$0
module top$lanes$0$taps$t7$prev(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t7$prev
module top$lanes$0$taps$t8(clock,read,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$0$taps$t8$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$0$taps$t8$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = read;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$0$taps$t8
module top$lanes$0$taps$t8$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t8$links$0
module top$lanes$0$taps$t8$prev(d,q,clock);
    
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
          
endmodule // top$lanes$0$taps$t8$prev
module top$lanes$1$taps(clock,beats,x,res,res_beat,t0s0,t0i1,t1s0,t1s1,t1i1,t1i2,t3s0,t3s1,t3i1,t3i2,t5s0,t5s1,t5s2,t5i1,t5i2,t5i3,t6s0,t6i1,t7s0,t7i1,t8s0,t8i1,t8il,a$0,a$1,a$2,a$3,a$4,a$5,a$6,a$7,a$8);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  [15:0] x;
    input wire  [63:0] res;
    input wire  res_beat;
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
    output reg  [63:0] a$0;
    output reg  [63:0] a$1;
    output reg  [63:0] a$2;
    output reg  [63:0] a$3;
    output reg  [63:0] a$4;
    output reg  [63:0] a$5;
    output reg  [63:0] a$6;
    output reg  [63:0] a$7;
    output reg  [63:0] a$8;
    
    // Constant declarations
    localparam  left8 = 1'b0;
    localparam  p_mask = 16'h1;
    
    // Stub signals
    reg  rows$clock;
    reg  [63:0] rows$beats;
    reg  [63:0] rows$res;
    reg  rows$res_beat;
    wire  [63:0] rows$tap$0;
    wire  [63:0] rows$tap$1;
    wire  [63:0] rows$tap$2;
    wire  [63:0] rows$tap$3;
    wire  [63:0] rows$tap$4;
    wire  [63:0] rows$tap$5;
    wire  [63:0] rows$tap$6;
    wire  [63:0] rows$tap$7;
    wire  [63:0] rows$tap$8;
    reg  t0$clock;
    reg  [63:0] t0$read;
    reg  t0$use_prev;
    reg  [63:0] t0$link_in$0;
    wire  [63:0] t0$pass$0;
    wire  [63:0] t0$a;
    reg  t1$clock;
    reg  [63:0] t1$read;
    reg  t1$use_prev;
    reg  [63:0] t1$link_in$0;
    reg  [63:0] t1$link_in$1;
    wire  [63:0] t1$pass$0;
    wire  [63:0] t1$pass$1;
    wire  [63:0] t1$a;
    reg  t2$clock;
    reg  [63:0] t2$read;
    reg  t2$use_prev;
    wire  [63:0] t2$a;
    reg  t3$clock;
    reg  [63:0] t3$read;
    reg  t3$use_prev;
    reg  [63:0] t3$link_in$0;
    reg  [63:0] t3$link_in$1;
    wire  [63:0] t3$pass$0;
    wire  [63:0] t3$pass$1;
    wire  [63:0] t3$a;
    reg  t4$clock;
    reg  [63:0] t4$read;
    reg  t4$use_prev;
    wire  [63:0] t4$a;
    reg  t5$clock;
    reg  [63:0] t5$read;
    reg  t5$use_prev;
    reg  [63:0] t5$link_in$0;
    reg  [63:0] t5$link_in$1;
    reg  [63:0] t5$link_in$2;
    wire  [63:0] t5$pass$0;
    wire  [63:0] t5$pass$1;
    wire  [63:0] t5$pass$2;
    wire  [63:0] t5$a;
    reg  t6$clock;
    reg  [63:0] t6$read;
    reg  t6$use_prev;
    reg  [63:0] t6$link_in$0;
    wire  [63:0] t6$pass$0;
    wire  [63:0] t6$a;
    reg  t7$clock;
    reg  [63:0] t7$read;
    reg  t7$use_prev;
    reg  [63:0] t7$link_in$0;
    wire  [63:0] t7$pass$0;
    wire  [63:0] t7$a;
    reg  t8$clock;
    reg  [63:0] t8$read;
    reg  t8$use_prev;
    reg  [63:0] t8$link_in$0;
    wire  [63:0] t8$pass$0;
    wire  [63:0] t8$a;
    
    // Local signals
    reg  first;
    reg  last;
    
    // Sub module instances
    top$lanes$1$taps$rows rows(
        .clock(rows$clock),
        .beats(rows$beats),
        .res(rows$res),
        .res_beat(rows$res_beat),
        .tap$0(rows$tap$0),
        .tap$1(rows$tap$1),
        .tap$2(rows$tap$2),
        .tap$3(rows$tap$3),
        .tap$4(rows$tap$4),
        .tap$5(rows$tap$5),
        .tap$6(rows$tap$6),
        .tap$7(rows$tap$7),
        .tap$8(rows$tap$8)
    );
    top$lanes$1$taps$t0 t0(
        .clock(t0$clock),
        .read(t0$read),
        .use_prev(t0$use_prev),
        .link_in$0(t0$link_in$0),
        .pass$0(t0$pass$0),
        .a(t0$a)
    );
    top$lanes$1$taps$t1 t1(
        .clock(t1$clock),
        .read(t1$read),
        .use_prev(t1$use_prev),
        .link_in$0(t1$link_in$0),
        .link_in$1(t1$link_in$1),
        .pass$0(t1$pass$0),
        .pass$1(t1$pass$1),
        .a(t1$a)
    );
    top$lanes$1$taps$t2 t2(
        .clock(t2$clock),
        .read(t2$read),
        .use_prev(t2$use_prev),
        .a(t2$a)
    );
    top$lanes$1$taps$t3 t3(
        .clock(t3$clock),
        .read(t3$read),
        .use_prev(t3$use_prev),
        .link_in$0(t3$link_in$0),
        .link_in$1(t3$link_in$1),
        .pass$0(t3$pass$0),
        .pass$1(t3$pass$1),
        .a(t3$a)
    );
    top$lanes$1$taps$t4 t4(
        .clock(t4$clock),
        .read(t4$read),
        .use_prev(t4$use_prev),
        .a(t4$a)
    );
    top$lanes$1$taps$t5 t5(
        .clock(t5$clock),
        .read(t5$read),
        .use_prev(t5$use_prev),
        .link_in$0(t5$link_in$0),
        .link_in$1(t5$link_in$1),
        .link_in$2(t5$link_in$2),
        .pass$0(t5$pass$0),
        .pass$1(t5$pass$1),
        .pass$2(t5$pass$2),
        .a(t5$a)
    );
    top$lanes$1$taps$t6 t6(
        .clock(t6$clock),
        .read(t6$read),
        .use_prev(t6$use_prev),
        .link_in$0(t6$link_in$0),
        .pass$0(t6$pass$0),
        .a(t6$a)
    );
    top$lanes$1$taps$t7 t7(
        .clock(t7$clock),
        .read(t7$read),
        .use_prev(t7$use_prev),
        .link_in$0(t7$link_in$0),
        .pass$0(t7$pass$0),
        .a(t7$a)
    );
    top$lanes$1$taps$t8 t8(
        .clock(t8$clock),
        .read(t8$read),
        .use_prev(t8$use_prev),
        .link_in$0(t8$link_in$0),
        .pass$0(t8$pass$0),
        .a(t8$a)
    );
    
    // Update code
    always @(*) begin
        rows$clock = clock;
        rows$beats = beats;
        rows$res = res;
        rows$res_beat = res_beat;
        first = (x & p_mask) == 'h0;
        last = (x & p_mask) == p_mask;
        t0$clock = clock;
        t0$read = rows$tap$0;
        t0$use_prev = 1'b0;
        t0$link_in$0 = t0i1;
        t0s0 = t0$pass$0;
        a$0 = t0$a;
        t1$clock = clock;
        t1$read = rows$tap$1;
        t1$use_prev = first;
        t1$link_in$0 = t1i1;
        t1$link_in$1 = t1i2;
        t1s0 = t1$pass$0;
        t1s1 = t1$pass$1;
        a$1 = t1$a;
        t2$clock = clock;
        t2$read = rows$tap$2;
        t2$use_prev = ~last;
        a$2 = t2$a;
        t3$clock = clock;
        t3$read = rows$tap$3;
        t3$use_prev = 1'b0;
        t3$link_in$0 = t3i1;
        t3$link_in$1 = t3i2;
        t3s0 = t3$pass$0;
        t3s1 = t3$pass$1;
        a$3 = t3$a;
        t4$clock = clock;
        t4$read = rows$tap$4;
        t4$use_prev = 1'b0;
        a$4 = t4$a;
        t5$clock = clock;
        t5$read = rows$tap$5;
        t5$use_prev = first;
        t5$link_in$0 = t5i1;
        t5$link_in$1 = t5i2;
        t5$link_in$2 = t5i3;
        t5s0 = t5$pass$0;
        t5s1 = t5$pass$1;
        t5s2 = t5$pass$2;
        a$5 = t5$a;
        t6$clock = clock;
        t6$read = rows$tap$6;
        t6$use_prev = ~last;
        t6$link_in$0 = t6i1;
        t6s0 = t6$pass$0;
        a$6 = t6$a;
        t7$clock = clock;
        t7$read = rows$tap$7;
        t7$use_prev = first;
        t7$link_in$0 = t7i1;
        t7s0 = t7$pass$0;
        a$7 = t7$a;
        t8$clock = clock;
        t8$read = rows$tap$8;
        t8$use_prev = ~last;
        if (left8) begin
            t8$link_in$0 = t8il;
        end
        else begin
            t8$link_in$0 = t8i1;
        end
        t8s0 = t8$pass$0;
        a$8 = t8$a;
    end
    
endmodule // top$lanes$1$taps
module top$lanes$1$taps$rows(clock,beats,res,res_beat,tap$0,tap$1,tap$2,tap$3,tap$4,tap$5,tap$6,tap$7,tap$8);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] beats;
    input wire  [63:0] res;
    input wire  res_beat;
    output reg  [63:0] tap$0;
    output reg  [63:0] tap$1;
    output reg  [63:0] tap$2;
    output reg  [63:0] tap$3;
    output reg  [63:0] tap$4;
    output reg  [63:0] tap$5;
    output reg  [63:0] tap$6;
    output reg  [63:0] tap$7;
    output reg  [63:0] tap$8;
    
    // Constant declarations
    localparam  pick$0 = 15'b100000000;
    localparam  pick$1 = 15'b1000000000;
    localparam  pick$2 = 15'b100000000;
    localparam  pick$3 = 15'b100000000000000;
    localparam  pick$4 = 15'b10000;
    localparam  pick$5 = 15'b10000000000000;
    localparam  pick$6 = 15'b1000000000000;
    localparam  pick$7 = 15'b1000;
    localparam  pick$8 = 15'b100;
    localparam  ring_less = 16'h10;
    
    // Stub signals
    reg  ring$clock;
    reg  [63:0] ring$data_in;
    reg  ring$write_enable;
    wire  [63:0] ring$data_out;
    reg  [15:0] ring$last;
    reg  beam0$clock;
    reg  [63:0] beam0$data_in;
    reg  beam0$write_enable;
    wire  [63:0] beam0$data_out;
    reg  [15:0] beam0$last;
    reg  beam1$clock;
    reg  [63:0] beam1$data_in;
    reg  beam1$write_enable;
    wire  [63:0] beam1$data_out;
    reg  [15:0] beam1$last;
    reg  [63:0] stage$0$d;
    wire  [63:0] stage$0$q;
    reg  stage$0$clock;
    reg  [63:0] stage$1$d;
    wire  [63:0] stage$1$q;
    reg  stage$1$clock;
    reg  [63:0] stage$2$d;
    wire  [63:0] stage$2$q;
    reg  stage$2$clock;
    reg  [63:0] stage$3$d;
    wire  [63:0] stage$3$q;
    reg  stage$3$clock;
    reg  [63:0] stage$4$d;
    wire  [63:0] stage$4$q;
    reg  stage$4$clock;
    reg  [63:0] stage$5$d;
    wire  [63:0] stage$5$q;
    reg  stage$5$clock;
    reg  [63:0] stage$6$d;
    wire  [63:0] stage$6$q;
    reg  stage$6$clock;
    reg  [63:0] stage$7$d;
    wire  [63:0] stage$7$q;
    reg  stage$7$clock;
    reg  [63:0] stage$8$d;
    wire  [63:0] stage$8$q;
    reg  stage$8$clock;
    reg  [63:0] stage$9$d;
    wire  [63:0] stage$9$q;
    reg  stage$9$clock;
    reg  [63:0] stage$10$d;
    wire  [63:0] stage$10$q;
    reg  stage$10$clock;
    reg  [63:0] stage$11$d;
    wire  [63:0] stage$11$q;
    reg  stage$11$clock;
    reg  [15:0] slice$d;
    wire  [15:0] slice$q;
    reg  slice$clock;
    reg  [15:0] beam$d;
    wire  [15:0] beam$q;
    reg  beam$clock;
    reg  [15:0] slice_less_beam$d;
    wire  [15:0] slice_less_beam$q;
    reg  slice_less_beam$clock;
    reg  [15:0] ring_last$d;
    wire  [15:0] ring_last$q;
    reg  ring_last$clock;
    reg  [15:0] beam_last$d;
    wire  [15:0] beam_last$q;
    reg  beam_last$clock;
    
    // Local signals
    reg  [63:0] cand$0;
    reg  [63:0] cand$1;
    reg  [63:0] cand$2;
    reg  [63:0] cand$3;
    reg  [63:0] cand$4;
    reg  [63:0] cand$5;
    reg  [63:0] cand$6;
    reg  [63:0] cand$7;
    reg  [63:0] cand$8;
    reg  [63:0] cand$9;
    reg  [63:0] cand$10;
    reg  [63:0] cand$11;
    reg  [63:0] cand$12;
    reg  [63:0] cand$13;
    reg  [63:0] cand$14;
    reg  [63:0] sel$0;
    reg  [63:0] sel$1;
    reg  [63:0] sel$2;
    reg  [63:0] sel$3;
    reg  [63:0] sel$4;
    reg  [63:0] sel$5;
    reg  [63:0] sel$6;
    reg  [63:0] sel$7;
    reg  [63:0] sel$8;
    
    // Sub module instances
    top$lanes$1$taps$rows$ring ring(
        .clock(ring$clock),
        .data_in(ring$data_in),
        .write_enable(ring$write_enable),
        .data_out(ring$data_out),
        .last(ring$last)
    );
    top$lanes$1$taps$rows$beam0 beam0(
        .clock(beam0$clock),
        .data_in(beam0$data_in),
        .write_enable(beam0$write_enable),
        .data_out(beam0$data_out),
        .last(beam0$last)
    );
    top$lanes$1$taps$rows$beam1 beam1(
        .clock(beam1$clock),
        .data_in(beam1$data_in),
        .write_enable(beam1$write_enable),
        .data_out(beam1$data_out),
        .last(beam1$last)
    );
    top$lanes$1$taps$rows$stage$0 stage$0(
        .d(stage$0$d),
        .q(stage$0$q),
        .clock(stage$0$clock)
    );
    top$lanes$1$taps$rows$stage$1 stage$1(
        .d(stage$1$d),
        .q(stage$1$q),
        .clock(stage$1$clock)
    );
    top$lanes$1$taps$rows$stage$2 stage$2(
        .d(stage$2$d),
        .q(stage$2$q),
        .clock(stage$2$clock)
    );
    top$lanes$1$taps$rows$stage$3 stage$3(
        .d(stage$3$d),
        .q(stage$3$q),
        .clock(stage$3$clock)
    );
    top$lanes$1$taps$rows$stage$4 stage$4(
        .d(stage$4$d),
        .q(stage$4$q),
        .clock(stage$4$clock)
    );
    top$lanes$1$taps$rows$stage$5 stage$5(
        .d(stage$5$d),
        .q(stage$5$q),
        .clock(stage$5$clock)
    );
    top$lanes$1$taps$rows$stage$6 stage$6(
        .d(stage$6$d),
        .q(stage$6$q),
        .clock(stage$6$clock)
    );
    top$lanes$1$taps$rows$stage$7 stage$7(
        .d(stage$7$d),
        .q(stage$7$q),
        .clock(stage$7$clock)
    );
    top$lanes$1$taps$rows$stage$8 stage$8(
        .d(stage$8$d),
        .q(stage$8$q),
        .clock(stage$8$clock)
    );
    top$lanes$1$taps$rows$stage$9 stage$9(
        .d(stage$9$d),
        .q(stage$9$q),
        .clock(stage$9$clock)
    );
    top$lanes$1$taps$rows$stage$10 stage$10(
        .d(stage$10$d),
        .q(stage$10$q),
        .clock(stage$10$clock)
    );
    top$lanes$1$taps$rows$stage$11 stage$11(
        .d(stage$11$d),
        .q(stage$11$q),
        .clock(stage$11$clock)
    );
    top$lanes$1$taps$rows$slice slice(
        .d(slice$d),
        .q(slice$q),
        .clock(slice$clock)
    );
    top$lanes$1$taps$rows$beam beam(
        .d(beam$d),
        .q(beam$q),
        .clock(beam$clock)
    );
    top$lanes$1$taps$rows$slice_less_beam slice_less_beam(
        .d(slice_less_beam$d),
        .q(slice_less_beam$q),
        .clock(slice_less_beam$clock)
    );
    top$lanes$1$taps$rows$ring_last ring_last(
        .d(ring_last$d),
        .q(ring_last$q),
        .clock(ring_last$clock)
    );
    top$lanes$1$taps$rows$beam_last beam_last(
        .d(beam_last$d),
        .q(beam_last$q),
        .clock(beam_last$clock)
    );
    
    // Update code
    always @(*) begin
        slice$clock = clock;
        beam$clock = clock;
        slice_less_beam$clock = clock;
        ring_last$clock = clock;
        beam_last$clock = clock;
        slice$d = slice$q;
        beam$d = beam$q;
        slice_less_beam$d = slice_less_beam$q;
        ring_last$d = ring_last$q;
        beam_last$d = beam_last$q;
        slice$d = beats[('h0)+:(16)];
        beam$d = beats[('h20)+:(16)];
        slice_less_beam$d = slice$q - beam$q;
        ring_last$d = slice_less_beam$q - ring_less;
        beam_last$d = beam$q - 'h1;
        ring$last = ring_last$q;
        beam0$last = beam_last$q;
        beam1$last = beam_last$q;
        ring$clock = clock;
        beam0$clock = clock;
        beam1$clock = clock;
        stage$0$clock = clock;
        stage$1$clock = clock;
        stage$2$clock = clock;
        stage$3$clock = clock;
        stage$4$clock = clock;
        stage$5$clock = clock;
        stage$6$clock = clock;
        stage$7$clock = clock;
        stage$8$clock = clock;
        stage$9$clock = clock;
        stage$10$clock = clock;
        stage$11$clock = clock;
        ring$data_in = res;
        ring$write_enable = res_beat;
        beam0$data_in = ring$data_out;
        beam0$write_enable = 1'b1;
        beam1$data_in = beam0$data_out;
        beam1$write_enable = 1'b1;
        cand$0 = ring$data_out;
        cand$5 = beam0$data_out;
        cand$10 = beam1$data_out;
        stage$0$d = cand$0;
        stage$1$d = stage$0$q;
        stage$2$d = stage$1$q;
        stage$3$d = stage$2$q;
        cand$1 = stage$0$q;
        cand$2 = stage$1$q;
        cand$3 = stage$2$q;
        cand$4 = stage$3$q;
        stage$4$d = cand$5;
        stage$5$d = stage$4$q;
        stage$6$d = stage$5$q;
        stage$7$d = stage$6$q;
        cand$6 = stage$4$q;
        cand$7 = stage$5$q;
        cand$8 = stage$6$q;
        cand$9 = stage$7$q;
        stage$8$d = cand$10;
        stage$9$d = stage$8$q;
        stage$10$d = stage$9$q;
        stage$11$d = stage$10$q;
        cand$11 = stage$8$q;
        cand$12 = stage$9$q;
        cand$13 = stage$10$q;
        cand$14 = stage$11$q;
        sel$0 = cand$0;
        if (pick$0[1]) begin
            sel$0 = cand$1;
        end
        if (pick$0[2]) begin
            sel$0 = cand$2;
        end
        if (pick$0[3]) begin
            sel$0 = cand$3;
        end
        if (pick$0[4]) begin
            sel$0 = cand$4;
        end
        if (pick$0[5]) begin
            sel$0 = cand$5;
        end
        if (pick$0[6]) begin
            sel$0 = cand$6;
        end
        if (pick$0[7]) begin
            sel$0 = cand$7;
        end
        if (pick$0[8]) begin
            sel$0 = cand$8;
        end
        if (pick$0[9]) begin
            sel$0 = cand$9;
        end
        if (pick$0[10]) begin
            sel$0 = cand$10;
        end
        if (pick$0[11]) begin
            sel$0 = cand$11;
        end
        if (pick$0[12]) begin
            sel$0 = cand$12;
        end
        if (pick$0[13]) begin
            sel$0 = cand$13;
        end
        if (pick$0[14]) begin
            sel$0 = cand$14;
        end
        tap$0 = sel$0;
        sel$1 = cand$0;
        if (pick$1[1]) begin
            sel$1 = cand$1;
        end
        if (pick$1[2]) begin
            sel$1 = cand$2;
        end
        if (pick$1[3]) begin
            sel$1 = cand$3;
        end
        if (pick$1[4]) begin
            sel$1 = cand$4;
        end
        if (pick$1[5]) begin
            sel$1 = cand$5;
        end
        if (pick$1[6]) begin
            sel$1 = cand$6;
        end
        if (pick$1[7]) begin
            sel$1 = cand$7;
        end
        if (pick$1[8]) begin
            sel$1 = cand$8;
        end
        if (pick$1[9]) begin
            sel$1 = cand$9;
        end
        if (pick$1[10]) begin
            sel$1 = cand$10;
        end
        if (pick$1[11]) begin
            sel$1 = cand$11;
        end
        if (pick$1[12]) begin
            sel$1 = cand$12;
        end
        if (pick$1[13]) begin
            sel$1 = cand$13;
        end
        if (pick$1[14]) begin
            sel$1 = cand$14;
        end
        tap$1 = sel$1;
        sel$2 = cand$0;
        if (pick$2[1]) begin
            sel$2 = cand$1;
        end
        if (pick$2[2]) begin
            sel$2 = cand$2;
        end
        if (pick$2[3]) begin
            sel$2 = cand$3;
        end
        if (pick$2[4]) begin
            sel$2 = cand$4;
        end
        if (pick$2[5]) begin
            sel$2 = cand$5;
        end
        if (pick$2[6]) begin
            sel$2 = cand$6;
        end
        if (pick$2[7]) begin
            sel$2 = cand$7;
        end
        if (pick$2[8]) begin
            sel$2 = cand$8;
        end
        if (pick$2[9]) begin
            sel$2 = cand$9;
        end
        if (pick$2[10]) begin
            sel$2 = cand$10;
        end
        if (pick$2[11]) begin
            sel$2 = cand$11;
        end
        if (pick$2[12]) begin
            sel$2 = cand$12;
        end
        if (pick$2[13]) begin
            sel$2 = cand$13;
        end
        if (pick$2[14]) begin
            sel$2 = cand$14;
        end
        tap$2 = sel$2;
        sel$3 = cand$0;
        if (pick$3[1]) begin
            sel$3 = cand$1;
        end
        if (pick$3[2]) begin
            sel$3 = cand$2;
        end
        if (pick$3[3]) begin
            sel$3 = cand$3;
        end
        if (pick$3[4]) begin
            sel$3 = cand$4;
        end
        if (pick$3[5]) begin
            sel$3 = cand$5;
        end
        if (pick$3[6]) begin
            sel$3 = cand$6;
        end
        if (pick$3[7]) begin
            sel$3 = cand$7;
        end
        if (pick$3[8]) begin
            sel$3 = cand$8;
        end
        if (pick$3[9]) begin
            sel$3 = cand$9;
        end
        if (pick$3[10]) begin
            sel$3 = cand$10;
        end
        if (pick$3[11]) begin
            sel$3 = cand$11;
        end
        if (pick$3[12]) begin
            sel$3 = cand$12;
        end
        if (pick$3[13]) begin
            sel$3 = cand$13;
        end
        if (pick$3[14]) begin
            sel$3 = cand$14;
        end
        tap$3 = sel$3;
        sel$4 = cand$0;
        if (pick$4[1]) begin
            sel$4 = cand$1;
        end
        if (pick$4[2]) begin
            sel$4 = cand$2;
        end
        if (pick$4[3]) begin
            sel$4 = cand$3;
        end
        if (pick$4[4]) begin
            sel$4 = cand$4;
        end
        if (pick$4[5]) begin
            sel$4 = cand$5;
        end
        if (pick$4[6]) begin
            sel$4 = cand$6;
        end
        if (pick$4[7]) begin
            sel$4 = cand$7;
        end
        if (pick$4[8]) begin
            sel$4 = cand$8;
        end
        if (pick$4[9]) begin
            sel$4 = cand$9;
        end
        if (pick$4[10]) begin
            sel$4 = cand$10;
        end
        if (pick$4[11]) begin
            sel$4 = cand$11;
        end
        if (pick$4[12]) begin
            sel$4 = cand$12;
        end
        if (pick$4[13]) begin
            sel$4 = cand$13;
        end
        if (pick$4[14]) begin
            sel$4 = cand$14;
        end
        tap$4 = sel$4;
        sel$5 = cand$0;
        if (pick$5[1]) begin
            sel$5 = cand$1;
        end
        if (pick$5[2]) begin
            sel$5 = cand$2;
        end
        if (pick$5[3]) begin
            sel$5 = cand$3;
        end
        if (pick$5[4]) begin
            sel$5 = cand$4;
        end
        if (pick$5[5]) begin
            sel$5 = cand$5;
        end
        if (pick$5[6]) begin
            sel$5 = cand$6;
        end
        if (pick$5[7]) begin
            sel$5 = cand$7;
        end
        if (pick$5[8]) begin
            sel$5 = cand$8;
        end
        if (pick$5[9]) begin
            sel$5 = cand$9;
        end
        if (pick$5[10]) begin
            sel$5 = cand$10;
        end
        if (pick$5[11]) begin
            sel$5 = cand$11;
        end
        if (pick$5[12]) begin
            sel$5 = cand$12;
        end
        if (pick$5[13]) begin
            sel$5 = cand$13;
        end
        if (pick$5[14]) begin
            sel$5 = cand$14;
        end
        tap$5 = sel$5;
        sel$6 = cand$0;
        if (pick$6[1]) begin
            sel$6 = cand$1;
        end
        if (pick$6[2]) begin
            sel$6 = cand$2;
        end
        if (pick$6[3]) begin
            sel$6 = cand$3;
        end
        if (pick$6[4]) begin
            sel$6 = cand$4;
        end
        if (pick$6[5]) begin
            sel$6 = cand$5;
        end
        if (pick$6[6]) begin
            sel$6 = cand$6;
        end
        if (pick$6[7]) begin
            sel$6 = cand$7;
        end
        if (pick$6[8]) begin
            sel$6 = cand$8;
        end
        if (pick$6[9]) begin
            sel$6 = cand$9;
        end
        if (pick$6[10]) begin
            sel$6 = cand$10;
        end
        if (pick$6[11]) begin
            sel$6 = cand$11;
        end
        if (pick$6[12]) begin
            sel$6 = cand$12;
        end
        if (pick$6[13]) begin
            sel$6 = cand$13;
        end
        if (pick$6[14]) begin
            sel$6 = cand$14;
        end
        tap$6 = sel$6;
        sel$7 = cand$0;
        if (pick$7[1]) begin
            sel$7 = cand$1;
        end
        if (pick$7[2]) begin
            sel$7 = cand$2;
        end
        if (pick$7[3]) begin
            sel$7 = cand$3;
        end
        if (pick$7[4]) begin
            sel$7 = cand$4;
        end
        if (pick$7[5]) begin
            sel$7 = cand$5;
        end
        if (pick$7[6]) begin
            sel$7 = cand$6;
        end
        if (pick$7[7]) begin
            sel$7 = cand$7;
        end
        if (pick$7[8]) begin
            sel$7 = cand$8;
        end
        if (pick$7[9]) begin
            sel$7 = cand$9;
        end
        if (pick$7[10]) begin
            sel$7 = cand$10;
        end
        if (pick$7[11]) begin
            sel$7 = cand$11;
        end
        if (pick$7[12]) begin
            sel$7 = cand$12;
        end
        if (pick$7[13]) begin
            sel$7 = cand$13;
        end
        if (pick$7[14]) begin
            sel$7 = cand$14;
        end
        tap$7 = sel$7;
        sel$8 = cand$0;
        if (pick$8[1]) begin
            sel$8 = cand$1;
        end
        if (pick$8[2]) begin
            sel$8 = cand$2;
        end
        if (pick$8[3]) begin
            sel$8 = cand$3;
        end
        if (pick$8[4]) begin
            sel$8 = cand$4;
        end
        if (pick$8[5]) begin
            sel$8 = cand$5;
        end
        if (pick$8[6]) begin
            sel$8 = cand$6;
        end
        if (pick$8[7]) begin
            sel$8 = cand$7;
        end
        if (pick$8[8]) begin
            sel$8 = cand$8;
        end
        if (pick$8[9]) begin
            sel$8 = cand$9;
        end
        if (pick$8[10]) begin
            sel$8 = cand$10;
        end
        if (pick$8[11]) begin
            sel$8 = cand$11;
        end
        if (pick$8[12]) begin
            sel$8 = cand$12;
        end
        if (pick$8[13]) begin
            sel$8 = cand$13;
        end
        if (pick$8[14]) begin
            sel$8 = cand$14;
        end
        tap$8 = sel$8;
    end
    
endmodule // top$lanes$1$taps$rows
module top$lanes$1$taps$rows$beam(d,q,clock);
    
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
endmodule // top$lanes$1$taps$rows$beam
module top$lanes$1$taps$rows$beam0(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'hd;
    localparam  has_ring = 1'b1;
    localparam  mask = 64'hff00ff00ff00ff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [63:0] one$d;
    wire  [63:0] one$q;
    reg  one$clock;
    reg  [63:0] two$d;
    wire  [63:0] two$q;
    reg  two$clock;
    reg  [63:0] short$d;
    wire  [63:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$1$taps$rows$beam0$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$1$taps$rows$beam0$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$1$taps$rows$beam0$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$1$taps$rows$beam0$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$1$taps$rows$beam0$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$1$taps$rows$beam0$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$1$taps$rows$beam0$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$1$taps$rows$beam0$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$1$taps$rows$beam0$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$1$taps$rows$beam0$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$1$taps$rows$beam0$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [63:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$1$taps$rows$beam0
module top$lanes$1$taps$rows$beam0$bound(d,q,clock);
    
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
endmodule // top$lanes$1$taps$rows$beam0$bound
module top$lanes$1$taps$rows$beam0$head(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$rows$beam0$head
module top$lanes$1$taps$rows$beam0$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$taps$rows$beam0$is_one
module top$lanes$1$taps$rows$beam0$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$taps$rows$beam0$is_short
module top$lanes$1$taps$rows$beam0$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$taps$rows$beam0$is_two
module top$lanes$1$taps$rows$beam0$one(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$beam0$one
module top$lanes$1$taps$rows$beam0$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$rows$beam0$ptr
module top$lanes$1$taps$rows$beam0$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [31:0] stored_word = {write_data[55:48], write_data[39:32], write_data[23:16], write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [31:0] mem_0_0[13:0];
    reg [31:0] rd_0;
    reg [31:0] q_0;
    reg [31:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[31:0] <= mem_0_0[read_address[3:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[3:0]] <= stored_word[31:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[31:24], 8'd0, r_0[23:16], 8'd0, r_0[15:8], 8'd0, r_0[7:0]};
    end
endmodule // top$lanes$1$taps$rows$beam0$ram
module top$lanes$1$taps$rows$beam0$rd(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$rows$beam0$rd
module top$lanes$1$taps$rows$beam0$short(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$beam0$short
module top$lanes$1$taps$rows$beam0$two(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$beam0$two
module top$lanes$1$taps$rows$beam1(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'hd;
    localparam  has_ring = 1'b1;
    localparam  mask = 64'hff00ff00ff00ff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [63:0] one$d;
    wire  [63:0] one$q;
    reg  one$clock;
    reg  [63:0] two$d;
    wire  [63:0] two$q;
    reg  two$clock;
    reg  [63:0] short$d;
    wire  [63:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$1$taps$rows$beam1$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$1$taps$rows$beam1$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$1$taps$rows$beam1$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$1$taps$rows$beam1$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$1$taps$rows$beam1$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$1$taps$rows$beam1$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$1$taps$rows$beam1$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$1$taps$rows$beam1$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$1$taps$rows$beam1$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$1$taps$rows$beam1$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$1$taps$rows$beam1$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [63:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$1$taps$rows$beam1
module top$lanes$1$taps$rows$beam1$bound(d,q,clock);
    
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
endmodule // top$lanes$1$taps$rows$beam1$bound
module top$lanes$1$taps$rows$beam1$head(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$rows$beam1$head
module top$lanes$1$taps$rows$beam1$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$taps$rows$beam1$is_one
module top$lanes$1$taps$rows$beam1$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$taps$rows$beam1$is_short
module top$lanes$1$taps$rows$beam1$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$taps$rows$beam1$is_two
module top$lanes$1$taps$rows$beam1$one(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$beam1$one
module top$lanes$1$taps$rows$beam1$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$rows$beam1$ptr
module top$lanes$1$taps$rows$beam1$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [31:0] stored_word = {write_data[55:48], write_data[39:32], write_data[23:16], write_data[7:0]};
    (* ram_style = "distributed" *)
    (* no_rw_check *)
    reg [31:0] mem_0_0[13:0];
    reg [31:0] rd_0;
    reg [31:0] q_0;
    reg [31:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[31:0] <= mem_0_0[read_address[3:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[3:0]] <= stored_word[31:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[31:24], 8'd0, r_0[23:16], 8'd0, r_0[15:8], 8'd0, r_0[7:0]};
    end
endmodule // top$lanes$1$taps$rows$beam1$ram
module top$lanes$1$taps$rows$beam1$rd(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$rows$beam1$rd
module top$lanes$1$taps$rows$beam1$short(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$beam1$short
module top$lanes$1$taps$rows$beam1$two(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$beam1$two
module top$lanes$1$taps$rows$beam_last(d,q,clock);
    
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
endmodule // top$lanes$1$taps$rows$beam_last
module top$lanes$1$taps$rows$ring(clock,data_in,write_enable,data_out,last);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] data_in;
    input wire  write_enable;
    output reg  [63:0] data_out;
    input wire  [15:0] last;
    
    // Constant declarations
    localparam  longest_last = 16'h1de;
    localparam  has_ring = 1'b1;
    localparam  mask = 64'hff00ff00ff00ff;
    
    // Stub signals
    reg  [15:0] ram$read_address;
    reg  ram$read_clock;
    wire  [63:0] ram$read_data;
    reg  [15:0] ram$write_address;
    reg  ram$write_clock;
    reg  [63:0] ram$write_data;
    reg  ram$write_enable;
    reg  [15:0] bound$d;
    wire  [15:0] bound$q;
    reg  bound$clock;
    reg  [15:0] head$d;
    wire  [15:0] head$q;
    reg  head$clock;
    reg  [15:0] rd$d;
    wire  [15:0] rd$q;
    reg  rd$clock;
    reg  [15:0] ptr$d;
    wire  [15:0] ptr$q;
    reg  ptr$clock;
    reg  [63:0] one$d;
    wire  [63:0] one$q;
    reg  one$clock;
    reg  [63:0] two$d;
    wire  [63:0] two$q;
    reg  two$clock;
    reg  [63:0] short$d;
    wire  [63:0] short$q;
    reg  short$clock;
    reg  is_short$d;
    wire  is_short$q;
    reg  is_short$clock;
    reg  is_one$d;
    wire  is_one$q;
    reg  is_one$clock;
    reg  is_two$d;
    wire  is_two$q;
    reg  is_two$clock;
    
    // Local signals
    reg  [15:0] next;
    
    // Sub module instances
    top$lanes$1$taps$rows$ring$ram ram(
        .read_address(ram$read_address),
        .read_clock(ram$read_clock),
        .read_data(ram$read_data),
        .write_address(ram$write_address),
        .write_clock(ram$write_clock),
        .write_data(ram$write_data),
        .write_enable(ram$write_enable)
    );
    top$lanes$1$taps$rows$ring$bound bound(
        .d(bound$d),
        .q(bound$q),
        .clock(bound$clock)
    );
    top$lanes$1$taps$rows$ring$head head(
        .d(head$d),
        .q(head$q),
        .clock(head$clock)
    );
    top$lanes$1$taps$rows$ring$rd rd(
        .d(rd$d),
        .q(rd$q),
        .clock(rd$clock)
    );
    top$lanes$1$taps$rows$ring$ptr ptr(
        .d(ptr$d),
        .q(ptr$q),
        .clock(ptr$clock)
    );
    top$lanes$1$taps$rows$ring$one one(
        .d(one$d),
        .q(one$q),
        .clock(one$clock)
    );
    top$lanes$1$taps$rows$ring$two two(
        .d(two$d),
        .q(two$q),
        .clock(two$clock)
    );
    top$lanes$1$taps$rows$ring$short short(
        .d(short$d),
        .q(short$q),
        .clock(short$clock)
    );
    top$lanes$1$taps$rows$ring$is_short is_short(
        .d(is_short$d),
        .q(is_short$q),
        .clock(is_short$clock)
    );
    top$lanes$1$taps$rows$ring$is_one is_one(
        .d(is_one$d),
        .q(is_one$q),
        .clock(is_one$clock)
    );
    top$lanes$1$taps$rows$ring$is_two is_two(
        .d(is_two$d),
        .q(is_two$q),
        .clock(is_two$clock)
    );
    
    // Update code
    reg  [63:0] data_out_pass;
    always @(*) begin
        bound$clock = clock;
        head$clock = clock;
        rd$clock = clock;
        ptr$clock = clock;
        one$clock = clock;
        two$clock = clock;
        short$clock = clock;
        is_short$clock = clock;
        is_one$clock = clock;
        is_two$clock = clock;
        bound$d = bound$q;
        head$d = head$q;
        rd$d = rd$q;
        ptr$d = ptr$q;
        one$d = one$q;
        two$d = two$q;
        short$d = short$q;
        is_short$d = is_short$q;
        is_one$d = is_one$q;
        is_two$d = is_two$q;
        ram$read_clock = clock;
        ram$write_clock = clock;
        bound$d = last - 'h2;
        is_short$d = last < 'h3;
        is_one$d = last == 'h0;
        is_two$d = last == 'h1;
        next = head$q + 'h1;
        if ((head$q >= bound$q) | (head$q >= longest_last)) begin
            next = 'h0;
        end
        head$d = next;
        rd$d = head$q;
        ptr$d = rd$q;
        ram$write_address = ptr$q;
        ram$write_data = data_in;
        ram$write_enable = write_enable & has_ring;
        ram$read_address = rd$q;
        one$d = one$q;
        if (write_enable) begin
            one$d = data_in & mask;
        end
        two$d = one$q;
        short$d = two$q;
        if (is_two$q) begin
            short$d = one$q;
        end
        if (is_one$q) begin
            short$d = short$q;
            if (write_enable) begin
                short$d = data_in & mask;
            end
        end
        data_out_pass = ram$read_data;
        if (is_short$q | ~has_ring) begin
            data_out_pass = short$q;
        end
        data_out = data_out_pass;
    end
    
endmodule // top$lanes$1$taps$rows$ring
module top$lanes$1$taps$rows$ring$bound(d,q,clock);
    
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
endmodule // top$lanes$1$taps$rows$ring$bound
module top$lanes$1$taps$rows$ring$head(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$rows$ring$head
module top$lanes$1$taps$rows$ring$is_one(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$taps$rows$ring$is_one
module top$lanes$1$taps$rows$ring$is_short(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$taps$rows$ring$is_short
module top$lanes$1$taps$rows$ring$is_two(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    (* keep *)
    always @(posedge clock) begin
       q <= d;
    end
endmodule // top$lanes$1$taps$rows$ring$is_two
module top$lanes$1$taps$rows$ring$one(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$ring$one
module top$lanes$1$taps$rows$ring$ptr(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$rows$ring$ptr
module top$lanes$1$taps$rows$ring$ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [15:0] read_address;
    input wire  read_clock;
    output reg  [63:0] read_data;
    input wire  [15:0] write_address;
    input wire  write_clock;
    input wire  [63:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    wire [31:0] stored_word = {write_data[55:48], write_data[39:32], write_data[23:16], write_data[7:0]};
    (* no_rw_check *)
    reg [31:0] mem_0_0[478:0];
    reg [31:0] rd_0;
    reg [31:0] q_0;
    reg [31:0] r_0;
    
    always @(posedge read_clock) begin
       rd_0[31:0] <= mem_0_0[read_address[8:0]];
       q_0 <= rd_0;
       r_0 <= q_0;
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem_0_0[write_address[8:0]] <= stored_word[31:0];
       end
    end
    
    always @(*) begin
       read_data = {8'd0, r_0[31:24], 8'd0, r_0[23:16], 8'd0, r_0[15:8], 8'd0, r_0[7:0]};
    end
endmodule // top$lanes$1$taps$rows$ring$ram
module top$lanes$1$taps$rows$ring$rd(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$taps$rows$ring$rd
module top$lanes$1$taps$rows$ring$short(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$ring$short
module top$lanes$1$taps$rows$ring$two(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$ring$two
module top$lanes$1$taps$rows$ring_last(d,q,clock);
    
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
endmodule // top$lanes$1$taps$rows$ring_last
module top$lanes$1$taps$rows$slice(d,q,clock);
    
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
endmodule // top$lanes$1$taps$rows$slice
module top$lanes$1$taps$rows$slice_less_beam(d,q,clock);
    
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
endmodule // top$lanes$1$taps$rows$slice_less_beam
module top$lanes$1$taps$rows$stage$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$0
module top$lanes$1$taps$rows$stage$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$1
module top$lanes$1$taps$rows$stage$10(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$10
module top$lanes$1$taps$rows$stage$11(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$11
module top$lanes$1$taps$rows$stage$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$2
module top$lanes$1$taps$rows$stage$3(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$3
module top$lanes$1$taps$rows$stage$4(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$4
module top$lanes$1$taps$rows$stage$5(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$5
module top$lanes$1$taps$rows$stage$6(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$6
module top$lanes$1$taps$rows$stage$7(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$7
module top$lanes$1$taps$rows$stage$8(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$8
module top$lanes$1$taps$rows$stage$9(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$rows$stage$9
module top$lanes$1$taps$t0(clock,read,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t0$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t0$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = read;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$1$taps$t0
module top$lanes$1$taps$t0$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t0$links$0
module top$lanes$1$taps$t0$prev(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t0$prev
module top$lanes$1$taps$t1(clock,read,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b0;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t1$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t1$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$1$taps$t1$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = read;
        pass$1 = links$0$q;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$1$taps$t1
module top$lanes$1$taps$t1$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t1$links$0
module top$lanes$1$taps$t1$links$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t1$links$1
module top$lanes$1$taps$t1$prev(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t1$prev
module top$lanes$1$taps$t2(clock,read,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Stub signals
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t2$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        stream = read;
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$1$taps$t2
module top$lanes$1$taps$t2$prev(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t2$prev
module top$lanes$1$taps$t3(clock,read,use_prev,link_in$0,link_in$1,pass$0,pass$1,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b0;
    localparam  take$1 = 1'b0;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t3$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t3$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$1$taps$t3$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        pass$0 = read;
        pass$1 = links$0$q;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$1$taps$t3
module top$lanes$1$taps$t3$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t3$links$0
module top$lanes$1$taps$t3$links$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t3$links$1
module top$lanes$1$taps$t3$prev(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t3$prev
module top$lanes$1$taps$t4(clock,read,use_prev,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    output reg  [63:0] a;
    
    // Stub signals
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t4$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        stream = read;
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$1$taps$t4
module top$lanes$1$taps$t4$prev(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t4$prev
module top$lanes$1$taps$t5(clock,read,use_prev,link_in$0,link_in$1,link_in$2,pass$0,pass$1,pass$2,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    input wire  [63:0] link_in$1;
    input wire  [63:0] link_in$2;
    output reg  [63:0] pass$0;
    output reg  [63:0] pass$1;
    output reg  [63:0] pass$2;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b1;
    localparam  take$1 = 1'b0;
    localparam  take$2 = 1'b0;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] links$1$d;
    wire  [63:0] links$1$q;
    reg  links$1$clock;
    reg  [63:0] links$2$d;
    wire  [63:0] links$2$q;
    reg  links$2$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t5$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t5$links$1 links$1(
        .d(links$1$d),
        .q(links$1$q),
        .clock(links$1$clock)
    );
    top$lanes$1$taps$t5$links$2 links$2(
        .d(links$2$d),
        .q(links$2$q),
        .clock(links$2$clock)
    );
    top$lanes$1$taps$t5$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        links$1$clock = clock;
        links$1$d = link_in$1;
        links$2$clock = clock;
        links$2$d = link_in$2;
        pass$0 = read;
        pass$1 = links$0$q;
        pass$2 = links$1$q;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        if (take$1) begin
            stream = links$1$q;
        end
        if (take$2) begin
            stream = links$2$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$1$taps$t5
module top$lanes$1$taps$t5$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t5$links$0
module top$lanes$1$taps$t5$links$1(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t5$links$1
module top$lanes$1$taps$t5$links$2(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t5$links$2
module top$lanes$1$taps$t5$prev(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t5$prev
module top$lanes$1$taps$t6(clock,read,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t6$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t6$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = read;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$1$taps$t6
module top$lanes$1$taps$t6$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t6$links$0
module top$lanes$1$taps$t6$prev(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t6$prev
module top$lanes$1$taps$t7(clock,read,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t7$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t7$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = read;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$1$taps$t7
module top$lanes$1$taps$t7$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t7$links$0
module top$lanes$1$taps$t7$prev(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t7$prev
module top$lanes$1$taps$t8(clock,read,use_prev,link_in$0,pass$0,a);
    
    // Module arguments
    input wire  clock;
    input wire  [63:0] read;
    input wire  use_prev;
    input wire  [63:0] link_in$0;
    output reg  [63:0] pass$0;
    output reg  [63:0] a;
    
    // Constant declarations
    localparam  take$0 = 1'b1;
    
    // Stub signals
    reg  [63:0] links$0$d;
    wire  [63:0] links$0$q;
    reg  links$0$clock;
    reg  [63:0] prev$d;
    wire  [63:0] prev$q;
    reg  prev$clock;
    
    // Local signals
    reg  [63:0] stream;
    
    // Sub module instances
    top$lanes$1$taps$t8$links$0 links$0(
        .d(links$0$d),
        .q(links$0$q),
        .clock(links$0$clock)
    );
    top$lanes$1$taps$t8$prev prev(
        .d(prev$d),
        .q(prev$q),
        .clock(prev$clock)
    );
    
    // Update code
    reg  [63:0] a_pass;
    always @(*) begin
        prev$clock = clock;
        prev$d = prev$q;
        links$0$clock = clock;
        links$0$d = link_in$0;
        pass$0 = read;
        stream = read;
        if (take$0) begin
            stream = links$0$q;
        end
        prev$d = stream;
        if (use_prev) begin
            a_pass = prev$q;
        end
        else begin
            a_pass = stream;
        end
        a = a_pass;
    end
    
endmodule // top$lanes$1$taps$t8
module top$lanes$1$taps$t8$links$0(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t8$links$0
module top$lanes$1$taps$t8$prev(d,q,clock);
    
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
          
endmodule // top$lanes$1$taps$t8$prev
