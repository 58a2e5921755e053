module top$lanes$0$compositor(clock,acc_r,acc_g,acc_b,acc_a,new_r,new_g,new_b,new_a,new_valid,out_r,out_g,out_b,out_a,order);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] acc_r;
    input wire  [15:0] acc_g;
    input wire  [15:0] acc_b;
    input wire  [15:0] acc_a;
    input wire  [31:0] new_r;
    input wire  [15:0] new_g;
    input wire  [15:0] new_b;
    input wire  [15:0] new_a;
    input wire  new_valid;
    output reg  [31:0] out_r;
    output reg  [15:0] out_g;
    output reg  [15:0] out_b;
    output reg  [15:0] out_a;
    input wire  [63:0] order;
    
    // Constant declarations
    localparam  over = 1'b1;
    localparam  scalar = 1'b0;
    
    // Stub signals
    reg  ch_r$clock;
    reg  [15:0] ch_r$front;
    reg  [15:0] ch_r$back;
    reg  [15:0] ch_r$front_alpha;
    wire  [15:0] ch_r$result;
    reg  ch_g$clock;
    reg  [15:0] ch_g$front;
    reg  [15:0] ch_g$back;
    reg  [15:0] ch_g$front_alpha;
    wire  [15:0] ch_g$result;
    reg  ch_b$clock;
    reg  [15:0] ch_b$front;
    reg  [15:0] ch_b$back;
    reg  [15:0] ch_b$front_alpha;
    wire  [15:0] ch_b$result;
    reg  ch_a$clock;
    reg  [15:0] ch_a$front;
    reg  [15:0] ch_a$back;
    reg  [15:0] ch_a$front_alpha;
    wire  [15:0] ch_a$result;
    reg  [31:0] scalar_q$d;
    wire  [31:0] scalar_q$q;
    reg  scalar_q$clock;
    reg  [31:0] scalar_qq$d;
    wire  [31:0] scalar_qq$q;
    reg  scalar_qq$clock;
    reg  [31:0] scalar_qqq$d;
    wire  [31:0] scalar_qqq$q;
    reg  scalar_qqq$clock;
    reg  [31:0] reg_r$d;
    wire  [31:0] reg_r$q;
    reg  reg_r$clock;
    reg  [15:0] reg_g$d;
    wire  [15:0] reg_g$q;
    reg  reg_g$clock;
    reg  [15:0] reg_b$d;
    wire  [15:0] reg_b$q;
    reg  reg_b$clock;
    reg  [15:0] reg_a$d;
    wire  [15:0] reg_a$q;
    reg  reg_a$clock;
    
    // Sub module instances
    top$lanes$0$compositor$ch_r ch_r(
        .clock(ch_r$clock),
        .front(ch_r$front),
        .back(ch_r$back),
        .front_alpha(ch_r$front_alpha),
        .result(ch_r$result)
    );
    top$lanes$0$compositor$ch_g ch_g(
        .clock(ch_g$clock),
        .front(ch_g$front),
        .back(ch_g$back),
        .front_alpha(ch_g$front_alpha),
        .result(ch_g$result)
    );
    top$lanes$0$compositor$ch_b ch_b(
        .clock(ch_b$clock),
        .front(ch_b$front),
        .back(ch_b$back),
        .front_alpha(ch_b$front_alpha),
        .result(ch_b$result)
    );
    top$lanes$0$compositor$ch_a ch_a(
        .clock(ch_a$clock),
        .front(ch_a$front),
        .back(ch_a$back),
        .front_alpha(ch_a$front_alpha),
        .result(ch_a$result)
    );
    top$lanes$0$compositor$scalar_q scalar_q(
        .d(scalar_q$d),
        .q(scalar_q$q),
        .clock(scalar_q$clock)
    );
    top$lanes$0$compositor$scalar_qq scalar_qq(
        .d(scalar_qq$d),
        .q(scalar_qq$q),
        .clock(scalar_qq$clock)
    );
    top$lanes$0$compositor$scalar_qqq scalar_qqq(
        .d(scalar_qqq$d),
        .q(scalar_qqq$q),
        .clock(scalar_qqq$clock)
    );
    top$lanes$0$compositor$reg_r reg_r(
        .d(reg_r$d),
        .q(reg_r$q),
        .clock(reg_r$clock)
    );
    top$lanes$0$compositor$reg_g reg_g(
        .d(reg_g$d),
        .q(reg_g$q),
        .clock(reg_g$clock)
    );
    top$lanes$0$compositor$reg_b reg_b(
        .d(reg_b$d),
        .q(reg_b$q),
        .clock(reg_b$clock)
    );
    top$lanes$0$compositor$reg_a reg_a(
        .d(reg_a$d),
        .q(reg_a$q),
        .clock(reg_a$clock)
    );
    
    // Update code
    always @(*) begin
        scalar_q$clock = clock;
        scalar_qq$clock = clock;
        scalar_qqq$clock = clock;
        reg_r$clock = clock;
        reg_g$clock = clock;
        reg_b$clock = clock;
        reg_a$clock = clock;
        scalar_q$d = scalar_q$q;
        scalar_qq$d = scalar_qq$q;
        scalar_qqq$d = scalar_qqq$q;
        reg_r$d = reg_r$q;
        reg_g$d = reg_g$q;
        reg_b$d = reg_b$q;
        reg_a$d = reg_a$q;
        ch_r$clock = clock;
        ch_g$clock = clock;
        ch_b$clock = clock;
        ch_a$clock = clock;
        if (order['h0]) begin
            ch_r$front = 16'(acc_r);
            ch_g$front = acc_g;
            ch_b$front = acc_b;
            ch_a$front = acc_a;
            ch_r$back = 16'(new_r);
            ch_g$back = new_g;
            ch_b$back = new_b;
            ch_a$back = new_a;
            ch_r$front_alpha = acc_a;
            ch_g$front_alpha = acc_a;
            ch_b$front_alpha = acc_a;
            ch_a$front_alpha = acc_a;
        end
        else begin
            ch_r$front = 16'(new_r);
            ch_g$front = new_g;
            ch_b$front = new_b;
            ch_a$front = new_a;
            ch_r$back = 16'(acc_r);
            ch_g$back = acc_g;
            ch_b$back = acc_b;
            ch_a$back = acc_a;
            ch_r$front_alpha = new_a;
            ch_g$front_alpha = new_a;
            ch_b$front_alpha = new_a;
            ch_a$front_alpha = new_a;
        end
        if (scalar) begin
            scalar_q$d = acc_r;
            if (order['h1]) begin
                if (new_valid & (new_r < acc_r)) begin
                    scalar_q$d = new_r;
                end
            end
            else if (new_valid & (new_r > acc_r)) begin
                scalar_q$d = new_r;
            end
        end
        else begin
            scalar_q$d = acc_r + new_r;
        end
        scalar_qq$d = scalar_q$q;
        scalar_qqq$d = scalar_qq$q;
        reg_r$d = scalar_qqq$q;
        reg_g$d = 'h0;
        reg_b$d = 'h0;
        reg_a$d = 'h0;
        if (over) begin
            reg_r$d = 32'(ch_r$result);
            reg_g$d = ch_g$result;
            reg_b$d = ch_b$result;
            reg_a$d = ch_a$result;
        end
        out_r = reg_r$q;
        out_g = reg_g$q;
        out_b = reg_b$q;
        out_a = reg_a$q;
    end
    
endmodule // top$lanes$0$compositor
module top$lanes$0$compositor$ch_a(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$0$compositor$ch_a$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$0$compositor$ch_a$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$0$compositor$ch_a$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$0$compositor$ch_a$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$0$compositor$ch_a$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$0$compositor$ch_a$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$0$compositor$ch_a
module top$lanes$0$compositor$ch_a$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_a$back_q
module top$lanes$0$compositor$ch_a$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_a$front_q
module top$lanes$0$compositor$ch_a$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_a$front_qq
module top$lanes$0$compositor$ch_a$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_a$front_qqq
module top$lanes$0$compositor$ch_a$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$0$compositor$ch_a$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$0$compositor$ch_a$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$0$compositor$ch_a$mul
module top$lanes$0$compositor$ch_a$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$0$compositor$ch_a$mul$p
module top$lanes$0$compositor$ch_a$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_a$mul$t
module top$lanes$0$compositor$ch_a$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_a$weight_q
module top$lanes$0$compositor$ch_b(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$0$compositor$ch_b$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$0$compositor$ch_b$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$0$compositor$ch_b$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$0$compositor$ch_b$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$0$compositor$ch_b$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$0$compositor$ch_b$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$0$compositor$ch_b
module top$lanes$0$compositor$ch_b$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_b$back_q
module top$lanes$0$compositor$ch_b$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_b$front_q
module top$lanes$0$compositor$ch_b$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_b$front_qq
module top$lanes$0$compositor$ch_b$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_b$front_qqq
module top$lanes$0$compositor$ch_b$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$0$compositor$ch_b$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$0$compositor$ch_b$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$0$compositor$ch_b$mul
module top$lanes$0$compositor$ch_b$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$0$compositor$ch_b$mul$p
module top$lanes$0$compositor$ch_b$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_b$mul$t
module top$lanes$0$compositor$ch_b$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_b$weight_q
module top$lanes$0$compositor$ch_g(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$0$compositor$ch_g$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$0$compositor$ch_g$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$0$compositor$ch_g$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$0$compositor$ch_g$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$0$compositor$ch_g$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$0$compositor$ch_g$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$0$compositor$ch_g
module top$lanes$0$compositor$ch_g$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_g$back_q
module top$lanes$0$compositor$ch_g$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_g$front_q
module top$lanes$0$compositor$ch_g$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_g$front_qq
module top$lanes$0$compositor$ch_g$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_g$front_qqq
module top$lanes$0$compositor$ch_g$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$0$compositor$ch_g$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$0$compositor$ch_g$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$0$compositor$ch_g$mul
module top$lanes$0$compositor$ch_g$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$0$compositor$ch_g$mul$p
module top$lanes$0$compositor$ch_g$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_g$mul$t
module top$lanes$0$compositor$ch_g$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_g$weight_q
module top$lanes$0$compositor$ch_r(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$0$compositor$ch_r$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$0$compositor$ch_r$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$0$compositor$ch_r$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$0$compositor$ch_r$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$0$compositor$ch_r$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$0$compositor$ch_r$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$0$compositor$ch_r
module top$lanes$0$compositor$ch_r$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_r$back_q
module top$lanes$0$compositor$ch_r$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_r$front_q
module top$lanes$0$compositor$ch_r$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_r$front_qq
module top$lanes$0$compositor$ch_r$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_r$front_qqq
module top$lanes$0$compositor$ch_r$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$0$compositor$ch_r$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$0$compositor$ch_r$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$0$compositor$ch_r$mul
module top$lanes$0$compositor$ch_r$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$0$compositor$ch_r$mul$p
module top$lanes$0$compositor$ch_r$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_r$mul$t
module top$lanes$0$compositor$ch_r$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$ch_r$weight_q
module top$lanes$0$compositor$reg_a(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$reg_a
module top$lanes$0$compositor$reg_b(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$reg_b
module top$lanes$0$compositor$reg_g(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$reg_g
module top$lanes$0$compositor$reg_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$reg_r
module top$lanes$0$compositor$scalar_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$scalar_q
module top$lanes$0$compositor$scalar_qq(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$scalar_qq
module top$lanes$0$compositor$scalar_qqq(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$0$compositor$scalar_qqq
module top$lanes$1$compositor(clock,acc_r,acc_g,acc_b,acc_a,new_r,new_g,new_b,new_a,new_valid,out_r,out_g,out_b,out_a,order);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] acc_r;
    input wire  [15:0] acc_g;
    input wire  [15:0] acc_b;
    input wire  [15:0] acc_a;
    input wire  [31:0] new_r;
    input wire  [15:0] new_g;
    input wire  [15:0] new_b;
    input wire  [15:0] new_a;
    input wire  new_valid;
    output reg  [31:0] out_r;
    output reg  [15:0] out_g;
    output reg  [15:0] out_b;
    output reg  [15:0] out_a;
    input wire  [63:0] order;
    
    // Constant declarations
    localparam  over = 1'b1;
    localparam  scalar = 1'b0;
    
    // Stub signals
    reg  ch_r$clock;
    reg  [15:0] ch_r$front;
    reg  [15:0] ch_r$back;
    reg  [15:0] ch_r$front_alpha;
    wire  [15:0] ch_r$result;
    reg  ch_g$clock;
    reg  [15:0] ch_g$front;
    reg  [15:0] ch_g$back;
    reg  [15:0] ch_g$front_alpha;
    wire  [15:0] ch_g$result;
    reg  ch_b$clock;
    reg  [15:0] ch_b$front;
    reg  [15:0] ch_b$back;
    reg  [15:0] ch_b$front_alpha;
    wire  [15:0] ch_b$result;
    reg  ch_a$clock;
    reg  [15:0] ch_a$front;
    reg  [15:0] ch_a$back;
    reg  [15:0] ch_a$front_alpha;
    wire  [15:0] ch_a$result;
    reg  [31:0] scalar_q$d;
    wire  [31:0] scalar_q$q;
    reg  scalar_q$clock;
    reg  [31:0] scalar_qq$d;
    wire  [31:0] scalar_qq$q;
    reg  scalar_qq$clock;
    reg  [31:0] scalar_qqq$d;
    wire  [31:0] scalar_qqq$q;
    reg  scalar_qqq$clock;
    reg  [31:0] reg_r$d;
    wire  [31:0] reg_r$q;
    reg  reg_r$clock;
    reg  [15:0] reg_g$d;
    wire  [15:0] reg_g$q;
    reg  reg_g$clock;
    reg  [15:0] reg_b$d;
    wire  [15:0] reg_b$q;
    reg  reg_b$clock;
    reg  [15:0] reg_a$d;
    wire  [15:0] reg_a$q;
    reg  reg_a$clock;
    
    // Sub module instances
    top$lanes$1$compositor$ch_r ch_r(
        .clock(ch_r$clock),
        .front(ch_r$front),
        .back(ch_r$back),
        .front_alpha(ch_r$front_alpha),
        .result(ch_r$result)
    );
    top$lanes$1$compositor$ch_g ch_g(
        .clock(ch_g$clock),
        .front(ch_g$front),
        .back(ch_g$back),
        .front_alpha(ch_g$front_alpha),
        .result(ch_g$result)
    );
    top$lanes$1$compositor$ch_b ch_b(
        .clock(ch_b$clock),
        .front(ch_b$front),
        .back(ch_b$back),
        .front_alpha(ch_b$front_alpha),
        .result(ch_b$result)
    );
    top$lanes$1$compositor$ch_a ch_a(
        .clock(ch_a$clock),
        .front(ch_a$front),
        .back(ch_a$back),
        .front_alpha(ch_a$front_alpha),
        .result(ch_a$result)
    );
    top$lanes$1$compositor$scalar_q scalar_q(
        .d(scalar_q$d),
        .q(scalar_q$q),
        .clock(scalar_q$clock)
    );
    top$lanes$1$compositor$scalar_qq scalar_qq(
        .d(scalar_qq$d),
        .q(scalar_qq$q),
        .clock(scalar_qq$clock)
    );
    top$lanes$1$compositor$scalar_qqq scalar_qqq(
        .d(scalar_qqq$d),
        .q(scalar_qqq$q),
        .clock(scalar_qqq$clock)
    );
    top$lanes$1$compositor$reg_r reg_r(
        .d(reg_r$d),
        .q(reg_r$q),
        .clock(reg_r$clock)
    );
    top$lanes$1$compositor$reg_g reg_g(
        .d(reg_g$d),
        .q(reg_g$q),
        .clock(reg_g$clock)
    );
    top$lanes$1$compositor$reg_b reg_b(
        .d(reg_b$d),
        .q(reg_b$q),
        .clock(reg_b$clock)
    );
    top$lanes$1$compositor$reg_a reg_a(
        .d(reg_a$d),
        .q(reg_a$q),
        .clock(reg_a$clock)
    );
    
    // Update code
    always @(*) begin
        scalar_q$clock = clock;
        scalar_qq$clock = clock;
        scalar_qqq$clock = clock;
        reg_r$clock = clock;
        reg_g$clock = clock;
        reg_b$clock = clock;
        reg_a$clock = clock;
        scalar_q$d = scalar_q$q;
        scalar_qq$d = scalar_qq$q;
        scalar_qqq$d = scalar_qqq$q;
        reg_r$d = reg_r$q;
        reg_g$d = reg_g$q;
        reg_b$d = reg_b$q;
        reg_a$d = reg_a$q;
        ch_r$clock = clock;
        ch_g$clock = clock;
        ch_b$clock = clock;
        ch_a$clock = clock;
        if (order['h0]) begin
            ch_r$front = 16'(acc_r);
            ch_g$front = acc_g;
            ch_b$front = acc_b;
            ch_a$front = acc_a;
            ch_r$back = 16'(new_r);
            ch_g$back = new_g;
            ch_b$back = new_b;
            ch_a$back = new_a;
            ch_r$front_alpha = acc_a;
            ch_g$front_alpha = acc_a;
            ch_b$front_alpha = acc_a;
            ch_a$front_alpha = acc_a;
        end
        else begin
            ch_r$front = 16'(new_r);
            ch_g$front = new_g;
            ch_b$front = new_b;
            ch_a$front = new_a;
            ch_r$back = 16'(acc_r);
            ch_g$back = acc_g;
            ch_b$back = acc_b;
            ch_a$back = acc_a;
            ch_r$front_alpha = new_a;
            ch_g$front_alpha = new_a;
            ch_b$front_alpha = new_a;
            ch_a$front_alpha = new_a;
        end
        if (scalar) begin
            scalar_q$d = acc_r;
            if (order['h1]) begin
                if (new_valid & (new_r < acc_r)) begin
                    scalar_q$d = new_r;
                end
            end
            else if (new_valid & (new_r > acc_r)) begin
                scalar_q$d = new_r;
            end
        end
        else begin
            scalar_q$d = acc_r + new_r;
        end
        scalar_qq$d = scalar_q$q;
        scalar_qqq$d = scalar_qq$q;
        reg_r$d = scalar_qqq$q;
        reg_g$d = 'h0;
        reg_b$d = 'h0;
        reg_a$d = 'h0;
        if (over) begin
            reg_r$d = 32'(ch_r$result);
            reg_g$d = ch_g$result;
            reg_b$d = ch_b$result;
            reg_a$d = ch_a$result;
        end
        out_r = reg_r$q;
        out_g = reg_g$q;
        out_b = reg_b$q;
        out_a = reg_a$q;
    end
    
endmodule // top$lanes$1$compositor
module top$lanes$1$compositor$ch_a(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$1$compositor$ch_a$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$1$compositor$ch_a$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$1$compositor$ch_a$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$1$compositor$ch_a$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$1$compositor$ch_a$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$1$compositor$ch_a$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$1$compositor$ch_a
module top$lanes$1$compositor$ch_a$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_a$back_q
module top$lanes$1$compositor$ch_a$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_a$front_q
module top$lanes$1$compositor$ch_a$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_a$front_qq
module top$lanes$1$compositor$ch_a$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_a$front_qqq
module top$lanes$1$compositor$ch_a$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$1$compositor$ch_a$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$1$compositor$ch_a$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$1$compositor$ch_a$mul
module top$lanes$1$compositor$ch_a$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$1$compositor$ch_a$mul$p
module top$lanes$1$compositor$ch_a$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_a$mul$t
module top$lanes$1$compositor$ch_a$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_a$weight_q
module top$lanes$1$compositor$ch_b(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$1$compositor$ch_b$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$1$compositor$ch_b$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$1$compositor$ch_b$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$1$compositor$ch_b$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$1$compositor$ch_b$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$1$compositor$ch_b$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$1$compositor$ch_b
module top$lanes$1$compositor$ch_b$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_b$back_q
module top$lanes$1$compositor$ch_b$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_b$front_q
module top$lanes$1$compositor$ch_b$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_b$front_qq
module top$lanes$1$compositor$ch_b$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_b$front_qqq
module top$lanes$1$compositor$ch_b$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$1$compositor$ch_b$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$1$compositor$ch_b$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$1$compositor$ch_b$mul
module top$lanes$1$compositor$ch_b$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$1$compositor$ch_b$mul$p
module top$lanes$1$compositor$ch_b$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_b$mul$t
module top$lanes$1$compositor$ch_b$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_b$weight_q
module top$lanes$1$compositor$ch_g(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$1$compositor$ch_g$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$1$compositor$ch_g$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$1$compositor$ch_g$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$1$compositor$ch_g$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$1$compositor$ch_g$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$1$compositor$ch_g$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$1$compositor$ch_g
module top$lanes$1$compositor$ch_g$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_g$back_q
module top$lanes$1$compositor$ch_g$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_g$front_q
module top$lanes$1$compositor$ch_g$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_g$front_qq
module top$lanes$1$compositor$ch_g$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_g$front_qqq
module top$lanes$1$compositor$ch_g$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$1$compositor$ch_g$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$1$compositor$ch_g$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$1$compositor$ch_g$mul
module top$lanes$1$compositor$ch_g$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$1$compositor$ch_g$mul$p
module top$lanes$1$compositor$ch_g$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_g$mul$t
module top$lanes$1$compositor$ch_g$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_g$weight_q
module top$lanes$1$compositor$ch_r(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$1$compositor$ch_r$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$1$compositor$ch_r$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$1$compositor$ch_r$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$1$compositor$ch_r$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$1$compositor$ch_r$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$1$compositor$ch_r$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$1$compositor$ch_r
module top$lanes$1$compositor$ch_r$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_r$back_q
module top$lanes$1$compositor$ch_r$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_r$front_q
module top$lanes$1$compositor$ch_r$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_r$front_qq
module top$lanes$1$compositor$ch_r$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_r$front_qqq
module top$lanes$1$compositor$ch_r$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$1$compositor$ch_r$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$1$compositor$ch_r$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$1$compositor$ch_r$mul
module top$lanes$1$compositor$ch_r$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$1$compositor$ch_r$mul$p
module top$lanes$1$compositor$ch_r$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_r$mul$t
module top$lanes$1$compositor$ch_r$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$ch_r$weight_q
module top$lanes$1$compositor$reg_a(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$reg_a
module top$lanes$1$compositor$reg_b(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$reg_b
module top$lanes$1$compositor$reg_g(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$reg_g
module top$lanes$1$compositor$reg_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$reg_r
module top$lanes$1$compositor$scalar_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$scalar_q
module top$lanes$1$compositor$scalar_qq(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$scalar_qq
module top$lanes$1$compositor$scalar_qqq(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$1$compositor$scalar_qqq
module top$lanes$2$compositor(clock,acc_r,acc_g,acc_b,acc_a,new_r,new_g,new_b,new_a,new_valid,out_r,out_g,out_b,out_a,order);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] acc_r;
    input wire  [15:0] acc_g;
    input wire  [15:0] acc_b;
    input wire  [15:0] acc_a;
    input wire  [31:0] new_r;
    input wire  [15:0] new_g;
    input wire  [15:0] new_b;
    input wire  [15:0] new_a;
    input wire  new_valid;
    output reg  [31:0] out_r;
    output reg  [15:0] out_g;
    output reg  [15:0] out_b;
    output reg  [15:0] out_a;
    input wire  [63:0] order;
    
    // Constant declarations
    localparam  over = 1'b1;
    localparam  scalar = 1'b0;
    
    // Stub signals
    reg  ch_r$clock;
    reg  [15:0] ch_r$front;
    reg  [15:0] ch_r$back;
    reg  [15:0] ch_r$front_alpha;
    wire  [15:0] ch_r$result;
    reg  ch_g$clock;
    reg  [15:0] ch_g$front;
    reg  [15:0] ch_g$back;
    reg  [15:0] ch_g$front_alpha;
    wire  [15:0] ch_g$result;
    reg  ch_b$clock;
    reg  [15:0] ch_b$front;
    reg  [15:0] ch_b$back;
    reg  [15:0] ch_b$front_alpha;
    wire  [15:0] ch_b$result;
    reg  ch_a$clock;
    reg  [15:0] ch_a$front;
    reg  [15:0] ch_a$back;
    reg  [15:0] ch_a$front_alpha;
    wire  [15:0] ch_a$result;
    reg  [31:0] scalar_q$d;
    wire  [31:0] scalar_q$q;
    reg  scalar_q$clock;
    reg  [31:0] scalar_qq$d;
    wire  [31:0] scalar_qq$q;
    reg  scalar_qq$clock;
    reg  [31:0] scalar_qqq$d;
    wire  [31:0] scalar_qqq$q;
    reg  scalar_qqq$clock;
    reg  [31:0] reg_r$d;
    wire  [31:0] reg_r$q;
    reg  reg_r$clock;
    reg  [15:0] reg_g$d;
    wire  [15:0] reg_g$q;
    reg  reg_g$clock;
    reg  [15:0] reg_b$d;
    wire  [15:0] reg_b$q;
    reg  reg_b$clock;
    reg  [15:0] reg_a$d;
    wire  [15:0] reg_a$q;
    reg  reg_a$clock;
    
    // Sub module instances
    top$lanes$2$compositor$ch_r ch_r(
        .clock(ch_r$clock),
        .front(ch_r$front),
        .back(ch_r$back),
        .front_alpha(ch_r$front_alpha),
        .result(ch_r$result)
    );
    top$lanes$2$compositor$ch_g ch_g(
        .clock(ch_g$clock),
        .front(ch_g$front),
        .back(ch_g$back),
        .front_alpha(ch_g$front_alpha),
        .result(ch_g$result)
    );
    top$lanes$2$compositor$ch_b ch_b(
        .clock(ch_b$clock),
        .front(ch_b$front),
        .back(ch_b$back),
        .front_alpha(ch_b$front_alpha),
        .result(ch_b$result)
    );
    top$lanes$2$compositor$ch_a ch_a(
        .clock(ch_a$clock),
        .front(ch_a$front),
        .back(ch_a$back),
        .front_alpha(ch_a$front_alpha),
        .result(ch_a$result)
    );
    top$lanes$2$compositor$scalar_q scalar_q(
        .d(scalar_q$d),
        .q(scalar_q$q),
        .clock(scalar_q$clock)
    );
    top$lanes$2$compositor$scalar_qq scalar_qq(
        .d(scalar_qq$d),
        .q(scalar_qq$q),
        .clock(scalar_qq$clock)
    );
    top$lanes$2$compositor$scalar_qqq scalar_qqq(
        .d(scalar_qqq$d),
        .q(scalar_qqq$q),
        .clock(scalar_qqq$clock)
    );
    top$lanes$2$compositor$reg_r reg_r(
        .d(reg_r$d),
        .q(reg_r$q),
        .clock(reg_r$clock)
    );
    top$lanes$2$compositor$reg_g reg_g(
        .d(reg_g$d),
        .q(reg_g$q),
        .clock(reg_g$clock)
    );
    top$lanes$2$compositor$reg_b reg_b(
        .d(reg_b$d),
        .q(reg_b$q),
        .clock(reg_b$clock)
    );
    top$lanes$2$compositor$reg_a reg_a(
        .d(reg_a$d),
        .q(reg_a$q),
        .clock(reg_a$clock)
    );
    
    // Update code
    always @(*) begin
        scalar_q$clock = clock;
        scalar_qq$clock = clock;
        scalar_qqq$clock = clock;
        reg_r$clock = clock;
        reg_g$clock = clock;
        reg_b$clock = clock;
        reg_a$clock = clock;
        scalar_q$d = scalar_q$q;
        scalar_qq$d = scalar_qq$q;
        scalar_qqq$d = scalar_qqq$q;
        reg_r$d = reg_r$q;
        reg_g$d = reg_g$q;
        reg_b$d = reg_b$q;
        reg_a$d = reg_a$q;
        ch_r$clock = clock;
        ch_g$clock = clock;
        ch_b$clock = clock;
        ch_a$clock = clock;
        if (order['h0]) begin
            ch_r$front = 16'(acc_r);
            ch_g$front = acc_g;
            ch_b$front = acc_b;
            ch_a$front = acc_a;
            ch_r$back = 16'(new_r);
            ch_g$back = new_g;
            ch_b$back = new_b;
            ch_a$back = new_a;
            ch_r$front_alpha = acc_a;
            ch_g$front_alpha = acc_a;
            ch_b$front_alpha = acc_a;
            ch_a$front_alpha = acc_a;
        end
        else begin
            ch_r$front = 16'(new_r);
            ch_g$front = new_g;
            ch_b$front = new_b;
            ch_a$front = new_a;
            ch_r$back = 16'(acc_r);
            ch_g$back = acc_g;
            ch_b$back = acc_b;
            ch_a$back = acc_a;
            ch_r$front_alpha = new_a;
            ch_g$front_alpha = new_a;
            ch_b$front_alpha = new_a;
            ch_a$front_alpha = new_a;
        end
        if (scalar) begin
            scalar_q$d = acc_r;
            if (order['h1]) begin
                if (new_valid & (new_r < acc_r)) begin
                    scalar_q$d = new_r;
                end
            end
            else if (new_valid & (new_r > acc_r)) begin
                scalar_q$d = new_r;
            end
        end
        else begin
            scalar_q$d = acc_r + new_r;
        end
        scalar_qq$d = scalar_q$q;
        scalar_qqq$d = scalar_qq$q;
        reg_r$d = scalar_qqq$q;
        reg_g$d = 'h0;
        reg_b$d = 'h0;
        reg_a$d = 'h0;
        if (over) begin
            reg_r$d = 32'(ch_r$result);
            reg_g$d = ch_g$result;
            reg_b$d = ch_b$result;
            reg_a$d = ch_a$result;
        end
        out_r = reg_r$q;
        out_g = reg_g$q;
        out_b = reg_b$q;
        out_a = reg_a$q;
    end
    
endmodule // top$lanes$2$compositor
module top$lanes$2$compositor$ch_a(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$2$compositor$ch_a$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$2$compositor$ch_a$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$2$compositor$ch_a$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$2$compositor$ch_a$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$2$compositor$ch_a$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$2$compositor$ch_a$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$2$compositor$ch_a
module top$lanes$2$compositor$ch_a$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_a$back_q
module top$lanes$2$compositor$ch_a$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_a$front_q
module top$lanes$2$compositor$ch_a$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_a$front_qq
module top$lanes$2$compositor$ch_a$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_a$front_qqq
module top$lanes$2$compositor$ch_a$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$2$compositor$ch_a$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$2$compositor$ch_a$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$2$compositor$ch_a$mul
module top$lanes$2$compositor$ch_a$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$2$compositor$ch_a$mul$p
module top$lanes$2$compositor$ch_a$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_a$mul$t
module top$lanes$2$compositor$ch_a$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_a$weight_q
module top$lanes$2$compositor$ch_b(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$2$compositor$ch_b$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$2$compositor$ch_b$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$2$compositor$ch_b$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$2$compositor$ch_b$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$2$compositor$ch_b$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$2$compositor$ch_b$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$2$compositor$ch_b
module top$lanes$2$compositor$ch_b$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_b$back_q
module top$lanes$2$compositor$ch_b$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_b$front_q
module top$lanes$2$compositor$ch_b$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_b$front_qq
module top$lanes$2$compositor$ch_b$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_b$front_qqq
module top$lanes$2$compositor$ch_b$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$2$compositor$ch_b$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$2$compositor$ch_b$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$2$compositor$ch_b$mul
module top$lanes$2$compositor$ch_b$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$2$compositor$ch_b$mul$p
module top$lanes$2$compositor$ch_b$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_b$mul$t
module top$lanes$2$compositor$ch_b$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_b$weight_q
module top$lanes$2$compositor$ch_g(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$2$compositor$ch_g$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$2$compositor$ch_g$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$2$compositor$ch_g$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$2$compositor$ch_g$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$2$compositor$ch_g$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$2$compositor$ch_g$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$2$compositor$ch_g
module top$lanes$2$compositor$ch_g$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_g$back_q
module top$lanes$2$compositor$ch_g$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_g$front_q
module top$lanes$2$compositor$ch_g$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_g$front_qq
module top$lanes$2$compositor$ch_g$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_g$front_qqq
module top$lanes$2$compositor$ch_g$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$2$compositor$ch_g$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$2$compositor$ch_g$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$2$compositor$ch_g$mul
module top$lanes$2$compositor$ch_g$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$2$compositor$ch_g$mul$p
module top$lanes$2$compositor$ch_g$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_g$mul$t
module top$lanes$2$compositor$ch_g$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_g$weight_q
module top$lanes$2$compositor$ch_r(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$2$compositor$ch_r$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$2$compositor$ch_r$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$2$compositor$ch_r$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$2$compositor$ch_r$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$2$compositor$ch_r$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$2$compositor$ch_r$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$2$compositor$ch_r
module top$lanes$2$compositor$ch_r$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_r$back_q
module top$lanes$2$compositor$ch_r$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_r$front_q
module top$lanes$2$compositor$ch_r$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_r$front_qq
module top$lanes$2$compositor$ch_r$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_r$front_qqq
module top$lanes$2$compositor$ch_r$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$2$compositor$ch_r$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$2$compositor$ch_r$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$2$compositor$ch_r$mul
module top$lanes$2$compositor$ch_r$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$2$compositor$ch_r$mul$p
module top$lanes$2$compositor$ch_r$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_r$mul$t
module top$lanes$2$compositor$ch_r$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$ch_r$weight_q
module top$lanes$2$compositor$reg_a(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$reg_a
module top$lanes$2$compositor$reg_b(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$reg_b
module top$lanes$2$compositor$reg_g(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$reg_g
module top$lanes$2$compositor$reg_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$reg_r
module top$lanes$2$compositor$scalar_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$scalar_q
module top$lanes$2$compositor$scalar_qq(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$scalar_qq
module top$lanes$2$compositor$scalar_qqq(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$2$compositor$scalar_qqq
module top$lanes$3$compositor(clock,acc_r,acc_g,acc_b,acc_a,new_r,new_g,new_b,new_a,new_valid,out_r,out_g,out_b,out_a,order);
    
    // Module arguments
    input wire  clock;
    input wire  [31:0] acc_r;
    input wire  [15:0] acc_g;
    input wire  [15:0] acc_b;
    input wire  [15:0] acc_a;
    input wire  [31:0] new_r;
    input wire  [15:0] new_g;
    input wire  [15:0] new_b;
    input wire  [15:0] new_a;
    input wire  new_valid;
    output reg  [31:0] out_r;
    output reg  [15:0] out_g;
    output reg  [15:0] out_b;
    output reg  [15:0] out_a;
    input wire  [63:0] order;
    
    // Constant declarations
    localparam  over = 1'b1;
    localparam  scalar = 1'b0;
    
    // Stub signals
    reg  ch_r$clock;
    reg  [15:0] ch_r$front;
    reg  [15:0] ch_r$back;
    reg  [15:0] ch_r$front_alpha;
    wire  [15:0] ch_r$result;
    reg  ch_g$clock;
    reg  [15:0] ch_g$front;
    reg  [15:0] ch_g$back;
    reg  [15:0] ch_g$front_alpha;
    wire  [15:0] ch_g$result;
    reg  ch_b$clock;
    reg  [15:0] ch_b$front;
    reg  [15:0] ch_b$back;
    reg  [15:0] ch_b$front_alpha;
    wire  [15:0] ch_b$result;
    reg  ch_a$clock;
    reg  [15:0] ch_a$front;
    reg  [15:0] ch_a$back;
    reg  [15:0] ch_a$front_alpha;
    wire  [15:0] ch_a$result;
    reg  [31:0] scalar_q$d;
    wire  [31:0] scalar_q$q;
    reg  scalar_q$clock;
    reg  [31:0] scalar_qq$d;
    wire  [31:0] scalar_qq$q;
    reg  scalar_qq$clock;
    reg  [31:0] scalar_qqq$d;
    wire  [31:0] scalar_qqq$q;
    reg  scalar_qqq$clock;
    reg  [31:0] reg_r$d;
    wire  [31:0] reg_r$q;
    reg  reg_r$clock;
    reg  [15:0] reg_g$d;
    wire  [15:0] reg_g$q;
    reg  reg_g$clock;
    reg  [15:0] reg_b$d;
    wire  [15:0] reg_b$q;
    reg  reg_b$clock;
    reg  [15:0] reg_a$d;
    wire  [15:0] reg_a$q;
    reg  reg_a$clock;
    
    // Sub module instances
    top$lanes$3$compositor$ch_r ch_r(
        .clock(ch_r$clock),
        .front(ch_r$front),
        .back(ch_r$back),
        .front_alpha(ch_r$front_alpha),
        .result(ch_r$result)
    );
    top$lanes$3$compositor$ch_g ch_g(
        .clock(ch_g$clock),
        .front(ch_g$front),
        .back(ch_g$back),
        .front_alpha(ch_g$front_alpha),
        .result(ch_g$result)
    );
    top$lanes$3$compositor$ch_b ch_b(
        .clock(ch_b$clock),
        .front(ch_b$front),
        .back(ch_b$back),
        .front_alpha(ch_b$front_alpha),
        .result(ch_b$result)
    );
    top$lanes$3$compositor$ch_a ch_a(
        .clock(ch_a$clock),
        .front(ch_a$front),
        .back(ch_a$back),
        .front_alpha(ch_a$front_alpha),
        .result(ch_a$result)
    );
    top$lanes$3$compositor$scalar_q scalar_q(
        .d(scalar_q$d),
        .q(scalar_q$q),
        .clock(scalar_q$clock)
    );
    top$lanes$3$compositor$scalar_qq scalar_qq(
        .d(scalar_qq$d),
        .q(scalar_qq$q),
        .clock(scalar_qq$clock)
    );
    top$lanes$3$compositor$scalar_qqq scalar_qqq(
        .d(scalar_qqq$d),
        .q(scalar_qqq$q),
        .clock(scalar_qqq$clock)
    );
    top$lanes$3$compositor$reg_r reg_r(
        .d(reg_r$d),
        .q(reg_r$q),
        .clock(reg_r$clock)
    );
    top$lanes$3$compositor$reg_g reg_g(
        .d(reg_g$d),
        .q(reg_g$q),
        .clock(reg_g$clock)
    );
    top$lanes$3$compositor$reg_b reg_b(
        .d(reg_b$d),
        .q(reg_b$q),
        .clock(reg_b$clock)
    );
    top$lanes$3$compositor$reg_a reg_a(
        .d(reg_a$d),
        .q(reg_a$q),
        .clock(reg_a$clock)
    );
    
    // Update code
    always @(*) begin
        scalar_q$clock = clock;
        scalar_qq$clock = clock;
        scalar_qqq$clock = clock;
        reg_r$clock = clock;
        reg_g$clock = clock;
        reg_b$clock = clock;
        reg_a$clock = clock;
        scalar_q$d = scalar_q$q;
        scalar_qq$d = scalar_qq$q;
        scalar_qqq$d = scalar_qqq$q;
        reg_r$d = reg_r$q;
        reg_g$d = reg_g$q;
        reg_b$d = reg_b$q;
        reg_a$d = reg_a$q;
        ch_r$clock = clock;
        ch_g$clock = clock;
        ch_b$clock = clock;
        ch_a$clock = clock;
        if (order['h0]) begin
            ch_r$front = 16'(acc_r);
            ch_g$front = acc_g;
            ch_b$front = acc_b;
            ch_a$front = acc_a;
            ch_r$back = 16'(new_r);
            ch_g$back = new_g;
            ch_b$back = new_b;
            ch_a$back = new_a;
            ch_r$front_alpha = acc_a;
            ch_g$front_alpha = acc_a;
            ch_b$front_alpha = acc_a;
            ch_a$front_alpha = acc_a;
        end
        else begin
            ch_r$front = 16'(new_r);
            ch_g$front = new_g;
            ch_b$front = new_b;
            ch_a$front = new_a;
            ch_r$back = 16'(acc_r);
            ch_g$back = acc_g;
            ch_b$back = acc_b;
            ch_a$back = acc_a;
            ch_r$front_alpha = new_a;
            ch_g$front_alpha = new_a;
            ch_b$front_alpha = new_a;
            ch_a$front_alpha = new_a;
        end
        if (scalar) begin
            scalar_q$d = acc_r;
            if (order['h1]) begin
                if (new_valid & (new_r < acc_r)) begin
                    scalar_q$d = new_r;
                end
            end
            else if (new_valid & (new_r > acc_r)) begin
                scalar_q$d = new_r;
            end
        end
        else begin
            scalar_q$d = acc_r + new_r;
        end
        scalar_qq$d = scalar_q$q;
        scalar_qqq$d = scalar_qq$q;
        reg_r$d = scalar_qqq$q;
        reg_g$d = 'h0;
        reg_b$d = 'h0;
        reg_a$d = 'h0;
        if (over) begin
            reg_r$d = 32'(ch_r$result);
            reg_g$d = ch_g$result;
            reg_b$d = ch_b$result;
            reg_a$d = ch_a$result;
        end
        out_r = reg_r$q;
        out_g = reg_g$q;
        out_b = reg_b$q;
        out_a = reg_a$q;
    end
    
endmodule // top$lanes$3$compositor
module top$lanes$3$compositor$ch_a(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$3$compositor$ch_a$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$3$compositor$ch_a$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$3$compositor$ch_a$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$3$compositor$ch_a$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$3$compositor$ch_a$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$3$compositor$ch_a$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$3$compositor$ch_a
module top$lanes$3$compositor$ch_a$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_a$back_q
module top$lanes$3$compositor$ch_a$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_a$front_q
module top$lanes$3$compositor$ch_a$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_a$front_qq
module top$lanes$3$compositor$ch_a$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_a$front_qqq
module top$lanes$3$compositor$ch_a$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$3$compositor$ch_a$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$3$compositor$ch_a$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$3$compositor$ch_a$mul
module top$lanes$3$compositor$ch_a$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$3$compositor$ch_a$mul$p
module top$lanes$3$compositor$ch_a$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_a$mul$t
module top$lanes$3$compositor$ch_a$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_a$weight_q
module top$lanes$3$compositor$ch_b(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$3$compositor$ch_b$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$3$compositor$ch_b$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$3$compositor$ch_b$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$3$compositor$ch_b$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$3$compositor$ch_b$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$3$compositor$ch_b$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$3$compositor$ch_b
module top$lanes$3$compositor$ch_b$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_b$back_q
module top$lanes$3$compositor$ch_b$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_b$front_q
module top$lanes$3$compositor$ch_b$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_b$front_qq
module top$lanes$3$compositor$ch_b$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_b$front_qqq
module top$lanes$3$compositor$ch_b$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$3$compositor$ch_b$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$3$compositor$ch_b$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$3$compositor$ch_b$mul
module top$lanes$3$compositor$ch_b$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$3$compositor$ch_b$mul$p
module top$lanes$3$compositor$ch_b$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_b$mul$t
module top$lanes$3$compositor$ch_b$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_b$weight_q
module top$lanes$3$compositor$ch_g(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$3$compositor$ch_g$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$3$compositor$ch_g$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$3$compositor$ch_g$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$3$compositor$ch_g$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$3$compositor$ch_g$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$3$compositor$ch_g$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$3$compositor$ch_g
module top$lanes$3$compositor$ch_g$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_g$back_q
module top$lanes$3$compositor$ch_g$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_g$front_q
module top$lanes$3$compositor$ch_g$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_g$front_qq
module top$lanes$3$compositor$ch_g$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_g$front_qqq
module top$lanes$3$compositor$ch_g$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$3$compositor$ch_g$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$3$compositor$ch_g$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$3$compositor$ch_g$mul
module top$lanes$3$compositor$ch_g$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$3$compositor$ch_g$mul$p
module top$lanes$3$compositor$ch_g$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_g$mul$t
module top$lanes$3$compositor$ch_g$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_g$weight_q
module top$lanes$3$compositor$ch_r(clock,front,back,front_alpha,result);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] front;
    input wire  [15:0] back;
    input wire  [15:0] front_alpha;
    output reg  [15:0] result;
    
    // Constant declarations
    localparam  m = 16'hff;
    
    // Stub signals
    reg  mul$clock;
    reg  [15:0] mul$a;
    reg  [15:0] mul$b;
    wire  [15:0] mul$y;
    reg  [15:0] weight_q$d;
    wire  [15:0] weight_q$q;
    reg  weight_q$clock;
    reg  [15:0] back_q$d;
    wire  [15:0] back_q$q;
    reg  back_q$clock;
    reg  [15:0] front_q$d;
    wire  [15:0] front_q$q;
    reg  front_q$clock;
    reg  [15:0] front_qq$d;
    wire  [15:0] front_qq$q;
    reg  front_qq$clock;
    reg  [15:0] front_qqq$d;
    wire  [15:0] front_qqq$q;
    reg  front_qqq$clock;
    
    // Local signals
    reg  [31:0] sum;
    
    // Sub module instances
    top$lanes$3$compositor$ch_r$mul mul(
        .clock(mul$clock),
        .a(mul$a),
        .b(mul$b),
        .y(mul$y)
    );
    top$lanes$3$compositor$ch_r$weight_q weight_q(
        .d(weight_q$d),
        .q(weight_q$q),
        .clock(weight_q$clock)
    );
    top$lanes$3$compositor$ch_r$back_q back_q(
        .d(back_q$d),
        .q(back_q$q),
        .clock(back_q$clock)
    );
    top$lanes$3$compositor$ch_r$front_q front_q(
        .d(front_q$d),
        .q(front_q$q),
        .clock(front_q$clock)
    );
    top$lanes$3$compositor$ch_r$front_qq front_qq(
        .d(front_qq$d),
        .q(front_qq$q),
        .clock(front_qq$clock)
    );
    top$lanes$3$compositor$ch_r$front_qqq front_qqq(
        .d(front_qqq$d),
        .q(front_qqq$q),
        .clock(front_qqq$clock)
    );
    
    // Update code
    reg  [15:0] result_pass;
    always @(*) begin
        weight_q$clock = clock;
        back_q$clock = clock;
        front_q$clock = clock;
        front_qq$clock = clock;
        front_qqq$clock = clock;
        weight_q$d = weight_q$q;
        back_q$d = back_q$q;
        front_q$d = front_q$q;
        front_qq$d = front_qq$q;
        front_qqq$d = front_qqq$q;
        weight_q$d = m - front_alpha;
        back_q$d = back;
        front_q$d = front;
        mul$clock = clock;
        mul$a = weight_q$q;
        mul$b = back_q$q;
        front_qq$d = front_q$q;
        front_qqq$d = front_qq$q;
        sum = 32'(front_qqq$q) + 32'(mul$y);
        result_pass = 16'(sum);
        if (sum > 32'(m)) begin
            result_pass = m;
        end
        result = result_pass;
    end
    
endmodule // top$lanes$3$compositor$ch_r
module top$lanes$3$compositor$ch_r$back_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_r$back_q
module top$lanes$3$compositor$ch_r$front_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_r$front_q
module top$lanes$3$compositor$ch_r$front_qq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_r$front_qq
module top$lanes$3$compositor$ch_r$front_qqq(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_r$front_qqq
module top$lanes$3$compositor$ch_r$mul(clock,a,b,y);
    
    // Module arguments
    input wire  clock;
    input wire  [15:0] a;
    input wire  [15:0] b;
    output reg  [15:0] y;
    
    // Constant declarations
    localparam  half = 'h80;
    localparam  shift = 8'h8;
    localparam  enabled = 1'b1;
    
    // Stub signals
    reg  p$clock;
    reg  [15:0] p$a;
    reg  [15:0] p$b;
    wire  [31:0] p$p;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    
    // Sub module instances
    top$lanes$3$compositor$ch_r$mul$p p(
        .clock(p$clock),
        .a(p$a),
        .b(p$b),
        .p(p$p)
    );
    top$lanes$3$compositor$ch_r$mul$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    
    // Update code
    reg  [15:0] y_pass;
    always @(*) begin
        t$clock = clock;
        t$d = t$q;
        p$clock = clock;
        p$a = a;
        p$b = b;
        t$d = p$p + half;
        y_pass = 16'((t$q + (t$q >> shift)) >> shift);
        if (~enabled) begin
            y_pass = 'h0;
        end
        y = y_pass;
    end
    
endmodule // top$lanes$3$compositor$ch_r$mul
module top$lanes$3$compositor$ch_r$mul$p(clock,a,b,p);
    
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
endmodule // top$lanes$3$compositor$ch_r$mul$p
module top$lanes$3$compositor$ch_r$mul$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_r$mul$t
module top$lanes$3$compositor$ch_r$weight_q(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$ch_r$weight_q
module top$lanes$3$compositor$reg_a(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$reg_a
module top$lanes$3$compositor$reg_b(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$reg_b
module top$lanes$3$compositor$reg_g(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$reg_g
module top$lanes$3$compositor$reg_r(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$reg_r
module top$lanes$3$compositor$scalar_q(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$scalar_q
module top$lanes$3$compositor$scalar_qq(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$scalar_qq
module top$lanes$3$compositor$scalar_qqq(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // top$lanes$3$compositor$scalar_qqq
