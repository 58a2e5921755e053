module top$pipeline$lanes$units$0(clock,a0,a1,b0,b1,c0,c1,d0,d1,offset,wx,wy,sample);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a0;
    input wire  [15:0] a1;
    input wire  [15:0] b0;
    input wire  [15:0] b1;
    input wire  [15:0] c0;
    input wire  [15:0] c1;
    input wire  [15:0] d0;
    input wire  [15:0] d1;
    input wire  [15:0] offset;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] sample;
    
    // Constant declarations
    localparam  widen = 8'h4;
    
    // Stub signals
    reg  [31:0] front_q$0$d;
    wire  [31:0] front_q$0$q;
    reg  front_q$0$clock;
    reg  [31:0] front_q$1$d;
    wire  [31:0] front_q$1$q;
    reg  front_q$1$clock;
    reg  [31:0] front_q$2$d;
    wire  [31:0] front_q$2$q;
    reg  front_q$2$clock;
    reg  [31:0] front_q$3$d;
    wire  [31:0] front_q$3$q;
    reg  front_q$3$clock;
    reg  [31:0] back_q$0$d;
    wire  [31:0] back_q$0$q;
    reg  back_q$0$clock;
    reg  [31:0] back_q$1$d;
    wire  [31:0] back_q$1$q;
    reg  back_q$1$clock;
    reg  [31:0] back_q$2$d;
    wire  [31:0] back_q$2$q;
    reg  back_q$2$clock;
    reg  [31:0] back_q$3$d;
    wire  [31:0] back_q$3$q;
    reg  back_q$3$clock;
    reg  [15:0] offset_q$d;
    wire  [15:0] offset_q$q;
    reg  offset_q$clock;
    reg  [15:0] wx_q$0$d;
    wire  [15:0] wx_q$0$q;
    reg  wx_q$0$clock;
    reg  [15:0] wx_q$1$d;
    wire  [15:0] wx_q$1$q;
    reg  wx_q$1$clock;
    reg  [15:0] wx_q$2$d;
    wire  [15:0] wx_q$2$q;
    reg  wx_q$2$clock;
    reg  [15:0] wy_q$0$d;
    wire  [15:0] wy_q$0$q;
    reg  wy_q$0$clock;
    reg  [15:0] wy_q$1$d;
    wire  [15:0] wy_q$1$q;
    reg  wy_q$1$clock;
    reg  [15:0] wy_q$2$d;
    wire  [15:0] wy_q$2$q;
    reg  wy_q$2$clock;
    reg  [15:0] wy_q$3$d;
    wire  [15:0] wy_q$3$q;
    reg  wy_q$3$clock;
    reg  [15:0] wy_q$4$d;
    wire  [15:0] wy_q$4$q;
    reg  wy_q$4$clock;
    reg  z$0$clock;
    reg  [31:0] z$0$a;
    reg  [31:0] z$0$b;
    reg  [15:0] z$0$w;
    wire  [31:0] z$0$y;
    reg  z$1$clock;
    reg  [31:0] z$1$a;
    reg  [31:0] z$1$b;
    reg  [15:0] z$1$w;
    wire  [31:0] z$1$y;
    reg  z$2$clock;
    reg  [31:0] z$2$a;
    reg  [31:0] z$2$b;
    reg  [15:0] z$2$w;
    wire  [31:0] z$2$y;
    reg  z$3$clock;
    reg  [31:0] z$3$a;
    reg  [31:0] z$3$b;
    reg  [15:0] z$3$w;
    wire  [31:0] z$3$y;
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    
    // Sub module instances
    top$pipeline$lanes$units$0$front_q$0 front_q$0(
        .d(front_q$0$d),
        .q(front_q$0$q),
        .clock(front_q$0$clock)
    );
    top$pipeline$lanes$units$0$front_q$1 front_q$1(
        .d(front_q$1$d),
        .q(front_q$1$q),
        .clock(front_q$1$clock)
    );
    top$pipeline$lanes$units$0$front_q$2 front_q$2(
        .d(front_q$2$d),
        .q(front_q$2$q),
        .clock(front_q$2$clock)
    );
    top$pipeline$lanes$units$0$front_q$3 front_q$3(
        .d(front_q$3$d),
        .q(front_q$3$q),
        .clock(front_q$3$clock)
    );
    top$pipeline$lanes$units$0$back_q$0 back_q$0(
        .d(back_q$0$d),
        .q(back_q$0$q),
        .clock(back_q$0$clock)
    );
    top$pipeline$lanes$units$0$back_q$1 back_q$1(
        .d(back_q$1$d),
        .q(back_q$1$q),
        .clock(back_q$1$clock)
    );
    top$pipeline$lanes$units$0$back_q$2 back_q$2(
        .d(back_q$2$d),
        .q(back_q$2$q),
        .clock(back_q$2$clock)
    );
    top$pipeline$lanes$units$0$back_q$3 back_q$3(
        .d(back_q$3$d),
        .q(back_q$3$q),
        .clock(back_q$3$clock)
    );
    top$pipeline$lanes$units$0$offset_q offset_q(
        .d(offset_q$d),
        .q(offset_q$q),
        .clock(offset_q$clock)
    );
    top$pipeline$lanes$units$0$wx_q$0 wx_q$0(
        .d(wx_q$0$d),
        .q(wx_q$0$q),
        .clock(wx_q$0$clock)
    );
    top$pipeline$lanes$units$0$wx_q$1 wx_q$1(
        .d(wx_q$1$d),
        .q(wx_q$1$q),
        .clock(wx_q$1$clock)
    );
    top$pipeline$lanes$units$0$wx_q$2 wx_q$2(
        .d(wx_q$2$d),
        .q(wx_q$2$q),
        .clock(wx_q$2$clock)
    );
    top$pipeline$lanes$units$0$wy_q$0 wy_q$0(
        .d(wy_q$0$d),
        .q(wy_q$0$q),
        .clock(wy_q$0$clock)
    );
    top$pipeline$lanes$units$0$wy_q$1 wy_q$1(
        .d(wy_q$1$d),
        .q(wy_q$1$q),
        .clock(wy_q$1$clock)
    );
    top$pipeline$lanes$units$0$wy_q$2 wy_q$2(
        .d(wy_q$2$d),
        .q(wy_q$2$q),
        .clock(wy_q$2$clock)
    );
    top$pipeline$lanes$units$0$wy_q$3 wy_q$3(
        .d(wy_q$3$d),
        .q(wy_q$3$q),
        .clock(wy_q$3$clock)
    );
    top$pipeline$lanes$units$0$wy_q$4 wy_q$4(
        .d(wy_q$4$d),
        .q(wy_q$4$q),
        .clock(wy_q$4$clock)
    );
    top$pipeline$lanes$units$0$z$0 z$0(
        .clock(z$0$clock),
        .a(z$0$a),
        .b(z$0$b),
        .w(z$0$w),
        .y(z$0$y)
    );
    top$pipeline$lanes$units$0$z$1 z$1(
        .clock(z$1$clock),
        .a(z$1$a),
        .b(z$1$b),
        .w(z$1$w),
        .y(z$1$y)
    );
    top$pipeline$lanes$units$0$z$2 z$2(
        .clock(z$2$clock),
        .a(z$2$a),
        .b(z$2$b),
        .w(z$2$w),
        .y(z$2$y)
    );
    top$pipeline$lanes$units$0$z$3 z$3(
        .clock(z$3$clock),
        .a(z$3$a),
        .b(z$3$b),
        .w(z$3$w),
        .y(z$3$y)
    );
    top$pipeline$lanes$units$0$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$pipeline$lanes$units$0$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$pipeline$lanes$units$0$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    
    // Update code
    always @(*) begin
        offset_q$clock = clock;
        offset_q$d = offset_q$q;
        wx_q$0$clock = clock;
        wx_q$1$clock = clock;
        wx_q$2$clock = clock;
        wy_q$0$clock = clock;
        wy_q$1$clock = clock;
        wy_q$2$clock = clock;
        wy_q$3$clock = clock;
        wy_q$4$clock = clock;
        front_q$0$clock = clock;
        back_q$0$clock = clock;
        z$0$clock = clock;
        front_q$1$clock = clock;
        back_q$1$clock = clock;
        z$1$clock = clock;
        front_q$2$clock = clock;
        back_q$2$clock = clock;
        z$2$clock = clock;
        front_q$3$clock = clock;
        back_q$3$clock = clock;
        z$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        front_q$0$d = 32'(a0) << widen;
        back_q$0$d = 32'(a1) << widen;
        front_q$1$d = 32'(b0) << widen;
        back_q$1$d = 32'(b1) << widen;
        front_q$2$d = 32'(c0) << widen;
        back_q$2$d = 32'(c1) << widen;
        front_q$3$d = 32'(d0) << widen;
        back_q$3$d = 32'(d1) << widen;
        offset_q$d = offset;
        wx_q$0$d = wx;
        wx_q$1$d = wx_q$0$q;
        wx_q$2$d = wx_q$1$q;
        wy_q$0$d = wy;
        wy_q$1$d = wy_q$0$q;
        wy_q$2$d = wy_q$1$q;
        wy_q$3$d = wy_q$2$q;
        wy_q$4$d = wy_q$3$q;
        z$0$a = front_q$0$q;
        z$0$b = back_q$0$q;
        z$0$w = offset_q$q;
        z$1$a = front_q$1$q;
        z$1$b = back_q$1$q;
        z$1$w = offset_q$q;
        z$2$a = front_q$2$q;
        z$2$b = back_q$2$q;
        z$2$w = offset_q$q;
        z$3$a = front_q$3$q;
        z$3$b = back_q$3$q;
        z$3$w = offset_q$q;
        top$a = z$0$y;
        top$b = z$1$y;
        top$w = wx_q$2$q;
        bottom$a = z$2$y;
        bottom$b = z$3$y;
        bottom$w = wx_q$2$q;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy_q$4$q;
        sample = vertical$y;
    end
    
endmodule // top$pipeline$lanes$units$0
module top$pipeline$lanes$units$0$back_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$back_q$0
module top$pipeline$lanes$units$0$back_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$back_q$1
module top$pipeline$lanes$units$0$back_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$back_q$2
module top$pipeline$lanes$units$0$back_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$back_q$3
module top$pipeline$lanes$units$0$bottom(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$0$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$0$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$0$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$0$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$0$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$0$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$0$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$0$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$0$bottom$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$0$bottom
module top$pipeline$lanes$units$0$bottom$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$bottom$a_q
module top$pipeline$lanes$units$0$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$bottom$a_q2
module top$pipeline$lanes$units$0$bottom$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$bottom$diff_q
module top$pipeline$lanes$units$0$bottom$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$0$bottom$narrow
module top$pipeline$lanes$units$0$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$bottom$prod_q
module top$pipeline$lanes$units$0$bottom$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$bottom$up_q
module top$pipeline$lanes$units$0$bottom$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$bottom$up_q2
module top$pipeline$lanes$units$0$bottom$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$bottom$w_q
module top$pipeline$lanes$units$0$bottom$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$bottom$y_q
module top$pipeline$lanes$units$0$front_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$front_q$0
module top$pipeline$lanes$units$0$front_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$front_q$1
module top$pipeline$lanes$units$0$front_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$front_q$2
module top$pipeline$lanes$units$0$front_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$front_q$3
module top$pipeline$lanes$units$0$offset_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$offset_q
module top$pipeline$lanes$units$0$top(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$0$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$0$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$0$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$0$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$0$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$0$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$0$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$0$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$0$top$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$0$top
module top$pipeline$lanes$units$0$top$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$top$a_q
module top$pipeline$lanes$units$0$top$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$top$a_q2
module top$pipeline$lanes$units$0$top$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$top$diff_q
module top$pipeline$lanes$units$0$top$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$0$top$narrow
module top$pipeline$lanes$units$0$top$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$top$prod_q
module top$pipeline$lanes$units$0$top$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$top$up_q
module top$pipeline$lanes$units$0$top$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$top$up_q2
module top$pipeline$lanes$units$0$top$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$top$w_q
module top$pipeline$lanes$units$0$top$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$top$y_q
module top$pipeline$lanes$units$0$vertical(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$0$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$0$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$0$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$0$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$0$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$0$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$0$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$0$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$0$vertical$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$0$vertical
module top$pipeline$lanes$units$0$vertical$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$vertical$a_q
module top$pipeline$lanes$units$0$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$vertical$a_q2
module top$pipeline$lanes$units$0$vertical$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$vertical$diff_q
module top$pipeline$lanes$units$0$vertical$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$0$vertical$narrow
module top$pipeline$lanes$units$0$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$vertical$prod_q
module top$pipeline$lanes$units$0$vertical$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$vertical$up_q
module top$pipeline$lanes$units$0$vertical$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$vertical$up_q2
module top$pipeline$lanes$units$0$vertical$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$vertical$w_q
module top$pipeline$lanes$units$0$vertical$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$vertical$y_q
module top$pipeline$lanes$units$0$wx_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$wx_q$0
module top$pipeline$lanes$units$0$wx_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$wx_q$1
module top$pipeline$lanes$units$0$wx_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$wx_q$2
module top$pipeline$lanes$units$0$wy_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$wy_q$0
module top$pipeline$lanes$units$0$wy_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$wy_q$1
module top$pipeline$lanes$units$0$wy_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$wy_q$2
module top$pipeline$lanes$units$0$wy_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$wy_q$3
module top$pipeline$lanes$units$0$wy_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$wy_q$4
module top$pipeline$lanes$units$0$z$0(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$0$z$0$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$0$z$0$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$0$z$0$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$0$z$0$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$0$z$0$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$0$z$0$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$0$z$0$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$0$z$0$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$0$z$0$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$0$z$0
module top$pipeline$lanes$units$0$z$0$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$0$a_q
module top$pipeline$lanes$units$0$z$0$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$z$0$a_q2
module top$pipeline$lanes$units$0$z$0$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$0$diff_q
module top$pipeline$lanes$units$0$z$0$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$0$z$0$narrow
module top$pipeline$lanes$units$0$z$0$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$z$0$prod_q
module top$pipeline$lanes$units$0$z$0$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$0$up_q
module top$pipeline$lanes$units$0$z$0$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$0$up_q2
module top$pipeline$lanes$units$0$z$0$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$0$w_q
module top$pipeline$lanes$units$0$z$0$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$0$y_q
module top$pipeline$lanes$units$0$z$1(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$0$z$1$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$0$z$1$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$0$z$1$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$0$z$1$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$0$z$1$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$0$z$1$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$0$z$1$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$0$z$1$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$0$z$1$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$0$z$1
module top$pipeline$lanes$units$0$z$1$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$1$a_q
module top$pipeline$lanes$units$0$z$1$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$z$1$a_q2
module top$pipeline$lanes$units$0$z$1$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$1$diff_q
module top$pipeline$lanes$units$0$z$1$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$0$z$1$narrow
module top$pipeline$lanes$units$0$z$1$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$z$1$prod_q
module top$pipeline$lanes$units$0$z$1$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$1$up_q
module top$pipeline$lanes$units$0$z$1$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$1$up_q2
module top$pipeline$lanes$units$0$z$1$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$1$w_q
module top$pipeline$lanes$units$0$z$1$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$1$y_q
module top$pipeline$lanes$units$0$z$2(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$0$z$2$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$0$z$2$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$0$z$2$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$0$z$2$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$0$z$2$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$0$z$2$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$0$z$2$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$0$z$2$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$0$z$2$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$0$z$2
module top$pipeline$lanes$units$0$z$2$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$2$a_q
module top$pipeline$lanes$units$0$z$2$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$z$2$a_q2
module top$pipeline$lanes$units$0$z$2$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$2$diff_q
module top$pipeline$lanes$units$0$z$2$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$0$z$2$narrow
module top$pipeline$lanes$units$0$z$2$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$z$2$prod_q
module top$pipeline$lanes$units$0$z$2$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$2$up_q
module top$pipeline$lanes$units$0$z$2$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$2$up_q2
module top$pipeline$lanes$units$0$z$2$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$2$w_q
module top$pipeline$lanes$units$0$z$2$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$2$y_q
module top$pipeline$lanes$units$0$z$3(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$0$z$3$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$0$z$3$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$0$z$3$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$0$z$3$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$0$z$3$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$0$z$3$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$0$z$3$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$0$z$3$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$0$z$3$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$0$z$3
module top$pipeline$lanes$units$0$z$3$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$3$a_q
module top$pipeline$lanes$units$0$z$3$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$z$3$a_q2
module top$pipeline$lanes$units$0$z$3$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$3$diff_q
module top$pipeline$lanes$units$0$z$3$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$0$z$3$narrow
module top$pipeline$lanes$units$0$z$3$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$0$z$3$prod_q
module top$pipeline$lanes$units$0$z$3$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$3$up_q
module top$pipeline$lanes$units$0$z$3$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$3$up_q2
module top$pipeline$lanes$units$0$z$3$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$3$w_q
module top$pipeline$lanes$units$0$z$3$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$0$z$3$y_q
module top$pipeline$lanes$units$1(clock,a0,a1,b0,b1,c0,c1,d0,d1,offset,wx,wy,sample);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a0;
    input wire  [15:0] a1;
    input wire  [15:0] b0;
    input wire  [15:0] b1;
    input wire  [15:0] c0;
    input wire  [15:0] c1;
    input wire  [15:0] d0;
    input wire  [15:0] d1;
    input wire  [15:0] offset;
    input wire  [15:0] wx;
    input wire  [15:0] wy;
    output reg  [31:0] sample;
    
    // Constant declarations
    localparam  widen = 8'h4;
    
    // Stub signals
    reg  [31:0] front_q$0$d;
    wire  [31:0] front_q$0$q;
    reg  front_q$0$clock;
    reg  [31:0] front_q$1$d;
    wire  [31:0] front_q$1$q;
    reg  front_q$1$clock;
    reg  [31:0] front_q$2$d;
    wire  [31:0] front_q$2$q;
    reg  front_q$2$clock;
    reg  [31:0] front_q$3$d;
    wire  [31:0] front_q$3$q;
    reg  front_q$3$clock;
    reg  [31:0] back_q$0$d;
    wire  [31:0] back_q$0$q;
    reg  back_q$0$clock;
    reg  [31:0] back_q$1$d;
    wire  [31:0] back_q$1$q;
    reg  back_q$1$clock;
    reg  [31:0] back_q$2$d;
    wire  [31:0] back_q$2$q;
    reg  back_q$2$clock;
    reg  [31:0] back_q$3$d;
    wire  [31:0] back_q$3$q;
    reg  back_q$3$clock;
    reg  [15:0] offset_q$d;
    wire  [15:0] offset_q$q;
    reg  offset_q$clock;
    reg  [15:0] wx_q$0$d;
    wire  [15:0] wx_q$0$q;
    reg  wx_q$0$clock;
    reg  [15:0] wx_q$1$d;
    wire  [15:0] wx_q$1$q;
    reg  wx_q$1$clock;
    reg  [15:0] wx_q$2$d;
    wire  [15:0] wx_q$2$q;
    reg  wx_q$2$clock;
    reg  [15:0] wy_q$0$d;
    wire  [15:0] wy_q$0$q;
    reg  wy_q$0$clock;
    reg  [15:0] wy_q$1$d;
    wire  [15:0] wy_q$1$q;
    reg  wy_q$1$clock;
    reg  [15:0] wy_q$2$d;
    wire  [15:0] wy_q$2$q;
    reg  wy_q$2$clock;
    reg  [15:0] wy_q$3$d;
    wire  [15:0] wy_q$3$q;
    reg  wy_q$3$clock;
    reg  [15:0] wy_q$4$d;
    wire  [15:0] wy_q$4$q;
    reg  wy_q$4$clock;
    reg  z$0$clock;
    reg  [31:0] z$0$a;
    reg  [31:0] z$0$b;
    reg  [15:0] z$0$w;
    wire  [31:0] z$0$y;
    reg  z$1$clock;
    reg  [31:0] z$1$a;
    reg  [31:0] z$1$b;
    reg  [15:0] z$1$w;
    wire  [31:0] z$1$y;
    reg  z$2$clock;
    reg  [31:0] z$2$a;
    reg  [31:0] z$2$b;
    reg  [15:0] z$2$w;
    wire  [31:0] z$2$y;
    reg  z$3$clock;
    reg  [31:0] z$3$a;
    reg  [31:0] z$3$b;
    reg  [15:0] z$3$w;
    wire  [31:0] z$3$y;
    reg  top$clock;
    reg  [31:0] top$a;
    reg  [31:0] top$b;
    reg  [15:0] top$w;
    wire  [31:0] top$y;
    reg  bottom$clock;
    reg  [31:0] bottom$a;
    reg  [31:0] bottom$b;
    reg  [15:0] bottom$w;
    wire  [31:0] bottom$y;
    reg  vertical$clock;
    reg  [31:0] vertical$a;
    reg  [31:0] vertical$b;
    reg  [15:0] vertical$w;
    wire  [31:0] vertical$y;
    
    // Sub module instances
    top$pipeline$lanes$units$1$front_q$0 front_q$0(
        .d(front_q$0$d),
        .q(front_q$0$q),
        .clock(front_q$0$clock)
    );
    top$pipeline$lanes$units$1$front_q$1 front_q$1(
        .d(front_q$1$d),
        .q(front_q$1$q),
        .clock(front_q$1$clock)
    );
    top$pipeline$lanes$units$1$front_q$2 front_q$2(
        .d(front_q$2$d),
        .q(front_q$2$q),
        .clock(front_q$2$clock)
    );
    top$pipeline$lanes$units$1$front_q$3 front_q$3(
        .d(front_q$3$d),
        .q(front_q$3$q),
        .clock(front_q$3$clock)
    );
    top$pipeline$lanes$units$1$back_q$0 back_q$0(
        .d(back_q$0$d),
        .q(back_q$0$q),
        .clock(back_q$0$clock)
    );
    top$pipeline$lanes$units$1$back_q$1 back_q$1(
        .d(back_q$1$d),
        .q(back_q$1$q),
        .clock(back_q$1$clock)
    );
    top$pipeline$lanes$units$1$back_q$2 back_q$2(
        .d(back_q$2$d),
        .q(back_q$2$q),
        .clock(back_q$2$clock)
    );
    top$pipeline$lanes$units$1$back_q$3 back_q$3(
        .d(back_q$3$d),
        .q(back_q$3$q),
        .clock(back_q$3$clock)
    );
    top$pipeline$lanes$units$1$offset_q offset_q(
        .d(offset_q$d),
        .q(offset_q$q),
        .clock(offset_q$clock)
    );
    top$pipeline$lanes$units$1$wx_q$0 wx_q$0(
        .d(wx_q$0$d),
        .q(wx_q$0$q),
        .clock(wx_q$0$clock)
    );
    top$pipeline$lanes$units$1$wx_q$1 wx_q$1(
        .d(wx_q$1$d),
        .q(wx_q$1$q),
        .clock(wx_q$1$clock)
    );
    top$pipeline$lanes$units$1$wx_q$2 wx_q$2(
        .d(wx_q$2$d),
        .q(wx_q$2$q),
        .clock(wx_q$2$clock)
    );
    top$pipeline$lanes$units$1$wy_q$0 wy_q$0(
        .d(wy_q$0$d),
        .q(wy_q$0$q),
        .clock(wy_q$0$clock)
    );
    top$pipeline$lanes$units$1$wy_q$1 wy_q$1(
        .d(wy_q$1$d),
        .q(wy_q$1$q),
        .clock(wy_q$1$clock)
    );
    top$pipeline$lanes$units$1$wy_q$2 wy_q$2(
        .d(wy_q$2$d),
        .q(wy_q$2$q),
        .clock(wy_q$2$clock)
    );
    top$pipeline$lanes$units$1$wy_q$3 wy_q$3(
        .d(wy_q$3$d),
        .q(wy_q$3$q),
        .clock(wy_q$3$clock)
    );
    top$pipeline$lanes$units$1$wy_q$4 wy_q$4(
        .d(wy_q$4$d),
        .q(wy_q$4$q),
        .clock(wy_q$4$clock)
    );
    top$pipeline$lanes$units$1$z$0 z$0(
        .clock(z$0$clock),
        .a(z$0$a),
        .b(z$0$b),
        .w(z$0$w),
        .y(z$0$y)
    );
    top$pipeline$lanes$units$1$z$1 z$1(
        .clock(z$1$clock),
        .a(z$1$a),
        .b(z$1$b),
        .w(z$1$w),
        .y(z$1$y)
    );
    top$pipeline$lanes$units$1$z$2 z$2(
        .clock(z$2$clock),
        .a(z$2$a),
        .b(z$2$b),
        .w(z$2$w),
        .y(z$2$y)
    );
    top$pipeline$lanes$units$1$z$3 z$3(
        .clock(z$3$clock),
        .a(z$3$a),
        .b(z$3$b),
        .w(z$3$w),
        .y(z$3$y)
    );
    top$pipeline$lanes$units$1$top top(
        .clock(top$clock),
        .a(top$a),
        .b(top$b),
        .w(top$w),
        .y(top$y)
    );
    top$pipeline$lanes$units$1$bottom bottom(
        .clock(bottom$clock),
        .a(bottom$a),
        .b(bottom$b),
        .w(bottom$w),
        .y(bottom$y)
    );
    top$pipeline$lanes$units$1$vertical vertical(
        .clock(vertical$clock),
        .a(vertical$a),
        .b(vertical$b),
        .w(vertical$w),
        .y(vertical$y)
    );
    
    // Update code
    always @(*) begin
        offset_q$clock = clock;
        offset_q$d = offset_q$q;
        wx_q$0$clock = clock;
        wx_q$1$clock = clock;
        wx_q$2$clock = clock;
        wy_q$0$clock = clock;
        wy_q$1$clock = clock;
        wy_q$2$clock = clock;
        wy_q$3$clock = clock;
        wy_q$4$clock = clock;
        front_q$0$clock = clock;
        back_q$0$clock = clock;
        z$0$clock = clock;
        front_q$1$clock = clock;
        back_q$1$clock = clock;
        z$1$clock = clock;
        front_q$2$clock = clock;
        back_q$2$clock = clock;
        z$2$clock = clock;
        front_q$3$clock = clock;
        back_q$3$clock = clock;
        z$3$clock = clock;
        top$clock = clock;
        bottom$clock = clock;
        vertical$clock = clock;
        front_q$0$d = 32'(a0) << widen;
        back_q$0$d = 32'(a1) << widen;
        front_q$1$d = 32'(b0) << widen;
        back_q$1$d = 32'(b1) << widen;
        front_q$2$d = 32'(c0) << widen;
        back_q$2$d = 32'(c1) << widen;
        front_q$3$d = 32'(d0) << widen;
        back_q$3$d = 32'(d1) << widen;
        offset_q$d = offset;
        wx_q$0$d = wx;
        wx_q$1$d = wx_q$0$q;
        wx_q$2$d = wx_q$1$q;
        wy_q$0$d = wy;
        wy_q$1$d = wy_q$0$q;
        wy_q$2$d = wy_q$1$q;
        wy_q$3$d = wy_q$2$q;
        wy_q$4$d = wy_q$3$q;
        z$0$a = front_q$0$q;
        z$0$b = back_q$0$q;
        z$0$w = offset_q$q;
        z$1$a = front_q$1$q;
        z$1$b = back_q$1$q;
        z$1$w = offset_q$q;
        z$2$a = front_q$2$q;
        z$2$b = back_q$2$q;
        z$2$w = offset_q$q;
        z$3$a = front_q$3$q;
        z$3$b = back_q$3$q;
        z$3$w = offset_q$q;
        top$a = z$0$y;
        top$b = z$1$y;
        top$w = wx_q$2$q;
        bottom$a = z$2$y;
        bottom$b = z$3$y;
        bottom$w = wx_q$2$q;
        vertical$a = top$y;
        vertical$b = bottom$y;
        vertical$w = wy_q$4$q;
        sample = vertical$y;
    end
    
endmodule // top$pipeline$lanes$units$1
module top$pipeline$lanes$units$1$back_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$back_q$0
module top$pipeline$lanes$units$1$back_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$back_q$1
module top$pipeline$lanes$units$1$back_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$back_q$2
module top$pipeline$lanes$units$1$back_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$back_q$3
module top$pipeline$lanes$units$1$bottom(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$1$bottom$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$1$bottom$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$1$bottom$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$1$bottom$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$1$bottom$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$1$bottom$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$1$bottom$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$1$bottom$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$1$bottom$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$1$bottom
module top$pipeline$lanes$units$1$bottom$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$bottom$a_q
module top$pipeline$lanes$units$1$bottom$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$bottom$a_q2
module top$pipeline$lanes$units$1$bottom$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$bottom$diff_q
module top$pipeline$lanes$units$1$bottom$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$1$bottom$narrow
module top$pipeline$lanes$units$1$bottom$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$bottom$prod_q
module top$pipeline$lanes$units$1$bottom$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$bottom$up_q
module top$pipeline$lanes$units$1$bottom$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$bottom$up_q2
module top$pipeline$lanes$units$1$bottom$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$bottom$w_q
module top$pipeline$lanes$units$1$bottom$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$bottom$y_q
module top$pipeline$lanes$units$1$front_q$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$front_q$0
module top$pipeline$lanes$units$1$front_q$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$front_q$1
module top$pipeline$lanes$units$1$front_q$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$front_q$2
module top$pipeline$lanes$units$1$front_q$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$front_q$3
module top$pipeline$lanes$units$1$offset_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$offset_q
module top$pipeline$lanes$units$1$top(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$1$top$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$1$top$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$1$top$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$1$top$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$1$top$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$1$top$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$1$top$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$1$top$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$1$top$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$1$top
module top$pipeline$lanes$units$1$top$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$top$a_q
module top$pipeline$lanes$units$1$top$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$top$a_q2
module top$pipeline$lanes$units$1$top$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$top$diff_q
module top$pipeline$lanes$units$1$top$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$1$top$narrow
module top$pipeline$lanes$units$1$top$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$top$prod_q
module top$pipeline$lanes$units$1$top$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$top$up_q
module top$pipeline$lanes$units$1$top$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$top$up_q2
module top$pipeline$lanes$units$1$top$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$top$w_q
module top$pipeline$lanes$units$1$top$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$top$y_q
module top$pipeline$lanes$units$1$vertical(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$1$vertical$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$1$vertical$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$1$vertical$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$1$vertical$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$1$vertical$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$1$vertical$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$1$vertical$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$1$vertical$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$1$vertical$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$1$vertical
module top$pipeline$lanes$units$1$vertical$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$vertical$a_q
module top$pipeline$lanes$units$1$vertical$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$vertical$a_q2
module top$pipeline$lanes$units$1$vertical$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$vertical$diff_q
module top$pipeline$lanes$units$1$vertical$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$1$vertical$narrow
module top$pipeline$lanes$units$1$vertical$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$vertical$prod_q
module top$pipeline$lanes$units$1$vertical$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$vertical$up_q
module top$pipeline$lanes$units$1$vertical$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$vertical$up_q2
module top$pipeline$lanes$units$1$vertical$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$vertical$w_q
module top$pipeline$lanes$units$1$vertical$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$vertical$y_q
module top$pipeline$lanes$units$1$wx_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$wx_q$0
module top$pipeline$lanes$units$1$wx_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$wx_q$1
module top$pipeline$lanes$units$1$wx_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$wx_q$2
module top$pipeline$lanes$units$1$wy_q$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$wy_q$0
module top$pipeline$lanes$units$1$wy_q$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$wy_q$1
module top$pipeline$lanes$units$1$wy_q$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$wy_q$2
module top$pipeline$lanes$units$1$wy_q$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$wy_q$3
module top$pipeline$lanes$units$1$wy_q$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$wy_q$4
module top$pipeline$lanes$units$1$z$0(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$1$z$0$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$1$z$0$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$1$z$0$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$1$z$0$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$1$z$0$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$1$z$0$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$1$z$0$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$1$z$0$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$1$z$0$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$1$z$0
module top$pipeline$lanes$units$1$z$0$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$0$a_q
module top$pipeline$lanes$units$1$z$0$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$z$0$a_q2
module top$pipeline$lanes$units$1$z$0$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$0$diff_q
module top$pipeline$lanes$units$1$z$0$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$1$z$0$narrow
module top$pipeline$lanes$units$1$z$0$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$z$0$prod_q
module top$pipeline$lanes$units$1$z$0$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$0$up_q
module top$pipeline$lanes$units$1$z$0$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$0$up_q2
module top$pipeline$lanes$units$1$z$0$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$0$w_q
module top$pipeline$lanes$units$1$z$0$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$0$y_q
module top$pipeline$lanes$units$1$z$1(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$1$z$1$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$1$z$1$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$1$z$1$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$1$z$1$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$1$z$1$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$1$z$1$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$1$z$1$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$1$z$1$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$1$z$1$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$1$z$1
module top$pipeline$lanes$units$1$z$1$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$1$a_q
module top$pipeline$lanes$units$1$z$1$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$z$1$a_q2
module top$pipeline$lanes$units$1$z$1$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$1$diff_q
module top$pipeline$lanes$units$1$z$1$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$1$z$1$narrow
module top$pipeline$lanes$units$1$z$1$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$z$1$prod_q
module top$pipeline$lanes$units$1$z$1$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$1$up_q
module top$pipeline$lanes$units$1$z$1$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$1$up_q2
module top$pipeline$lanes$units$1$z$1$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$1$w_q
module top$pipeline$lanes$units$1$z$1$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$1$y_q
module top$pipeline$lanes$units$1$z$2(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$1$z$2$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$1$z$2$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$1$z$2$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$1$z$2$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$1$z$2$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$1$z$2$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$1$z$2$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$1$z$2$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$1$z$2$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$1$z$2
module top$pipeline$lanes$units$1$z$2$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$2$a_q
module top$pipeline$lanes$units$1$z$2$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$z$2$a_q2
module top$pipeline$lanes$units$1$z$2$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$2$diff_q
module top$pipeline$lanes$units$1$z$2$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$1$z$2$narrow
module top$pipeline$lanes$units$1$z$2$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$z$2$prod_q
module top$pipeline$lanes$units$1$z$2$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$2$up_q
module top$pipeline$lanes$units$1$z$2$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$2$up_q2
module top$pipeline$lanes$units$1$z$2$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$2$w_q
module top$pipeline$lanes$units$1$z$2$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$2$y_q
module top$pipeline$lanes$units$1$z$3(clock,a,b,w,y);
    
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
    localparam  split = 1'b0;
    
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
    top$pipeline$lanes$units$1$z$3$up_q up_q(
        .d(up_q$d),
        .q(up_q$q),
        .clock(up_q$clock)
    );
    top$pipeline$lanes$units$1$z$3$a_q a_q(
        .d(a_q$d),
        .q(a_q$q),
        .clock(a_q$clock)
    );
    top$pipeline$lanes$units$1$z$3$diff_q diff_q(
        .d(diff_q$d),
        .q(diff_q$q),
        .clock(diff_q$clock)
    );
    top$pipeline$lanes$units$1$z$3$w_q w_q(
        .d(w_q$d),
        .q(w_q$q),
        .clock(w_q$clock)
    );
    top$pipeline$lanes$units$1$z$3$narrow narrow(
        .clock(narrow$clock),
        .a(narrow$a),
        .b(narrow$b),
        .p(narrow$p)
    );
    top$pipeline$lanes$units$1$z$3$up_q2 up_q2(
        .d(up_q2$d),
        .q(up_q2$q),
        .clock(up_q2$clock)
    );
    top$pipeline$lanes$units$1$z$3$a_q2 a_q2(
        .d(a_q2$d),
        .q(a_q2$q),
        .clock(a_q2$clock)
    );
    top$pipeline$lanes$units$1$z$3$prod_q prod_q(
        .d(prod_q$d),
        .q(prod_q$q),
        .clock(prod_q$clock)
    );
    top$pipeline$lanes$units$1$z$3$y_q y_q(
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
    
endmodule // top$pipeline$lanes$units$1$z$3
module top$pipeline$lanes$units$1$z$3$a_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$3$a_q
module top$pipeline$lanes$units$1$z$3$a_q2(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$z$3$a_q2
module top$pipeline$lanes$units$1$z$3$diff_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$3$diff_q
module top$pipeline$lanes$units$1$z$3$narrow(clock,a,b,p);
    
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
endmodule // top$pipeline$lanes$units$1$z$3$narrow
module top$pipeline$lanes$units$1$z$3$prod_q(d,q,clock);
    
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
          
endmodule // top$pipeline$lanes$units$1$z$3$prod_q
module top$pipeline$lanes$units$1$z$3$up_q(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$3$up_q
module top$pipeline$lanes$units$1$z$3$up_q2(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$3$up_q2
module top$pipeline$lanes$units$1$z$3$w_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$3$w_q
module top$pipeline$lanes$units$1$z$3$y_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$pipeline$lanes$units$1$z$3$y_q
